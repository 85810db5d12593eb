package org.miron.bt.formats;

import static org.miron.bt.formats.TreeEdits.*;

import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Precondition;
import org.miron.bt.bt.Subtree;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.validation.BtIssueCodes;
import org.miron.bt.validation.BtVersions;

/** Version 4 to 3 where BehaviorTree.CPP 3 has an equivalent; the inverse of V3ToV4. */
final class V4ToV3 {
    private static final Set<String> V3_STATUSES = Set.of("SUCCESS", "FAILURE", "RUNNING");

    private V4ToV3() {
    }

    static void check(TreeNode node, List<ConversionProblem> problems) {
        String tag = node.getTag();
        if (node instanceof Precondition) {
            String otherwise = node.attribute("else");
            if (BlackboardChecks.fromCondition(String.valueOf(node.attribute("if"))) == null
                    || otherwise != null && !V3_STATUSES.contains(otherwise)) {
                problems.add(new ConversionProblem(node, "Precondition has no BehaviorTree.CPP 3 equivalent "
                        + "(only if=\"A == B\" of keys and literals, with else SUCCESS, FAILURE or RUNNING, "
                        + "is a BlackboardCheck)", BtIssueCodes.NO_V3_EQUIVALENT));
            }
        } else if (tag != null && BtVersions.V4_ONLY_TAGS.containsKey(tag)
                && BtVersions.V4_ONLY_TAGS.get(tag).isEmpty()) {
            problems.add(new ConversionProblem(node, tag + " has no BehaviorTree.CPP 3 equivalent",
                    BtIssueCodes.NO_V3_EQUIVALENT));
        }
        for (Attribute attribute : node.getAttributes()) {
            if (BtVersions.SCRIPT_DIRECTIVES.contains(attribute.getName())) {
                problems.add(new ConversionProblem(attribute, attribute.getName() + " (on " + tag
                        + ") has no BehaviorTree.CPP 3 equivalent", BtIssueCodes.NO_V3_EQUIVALENT));
            }
        }
    }

    static void apply(TreeNode node, Map<EObject, EObject> replacements) {
        String tag = node.getTag();
        if ("SequenceWithMemory".equals(tag)) {
            node.setTag("SequenceStar");
        } else if ("Control".equals(tag) && "SequenceWithMemory".equals(node.attribute("ID"))) {
            set(node.getAttributes(), "ID", "SequenceStar");
        } else if (node instanceof Parallel && "Parallel".equals(tag)) {
            for (Map.Entry<String, String> port : BtVersions.PARALLEL_PORTS.entrySet()) {
                rename(node.getAttributes(), port.getValue(), port.getKey());
            }
        } else if (node instanceof Subtree) {
            subtree(node, replacements);
        } else if (node instanceof Precondition) {
            precondition(node, replacements);
        }
    }

    /**
     * With _autoremap (the mark of a v3 SubTreePlus) or a literal port: SubTreePlus, ports as
     * written ({=} spelled out). Otherwise a plain SubTree, whose ports name the parent's keys.
     */
    private static void subtree(TreeNode node, Map<EObject, EObject> replacements) {
        List<Attribute> attributes = node.getAttributes();
        for (Attribute attribute : attributes) {
            if (attribute.getValue().equals("{=}")) {
                attribute.setValue("{" + attribute.getName() + "}");
            }
        }
        boolean literal = attributes.stream().anyMatch(a -> !a.getName().equals("name")
                && !a.getName().equals("_autoremap") && !isRemap(a.getValue()));
        String autoremap = node.attribute("_autoremap");
        if (autoremap != null || literal) {
            TreeNode plus = become(node, BtPackage.Literals.SUBTREE_PLUS, "SubTreePlus", replacements);
            if (autoremap != null && V3ToV4.isTrue(autoremap)) {
                rename(plus.getAttributes(), "_autoremap", "__autoremap");
            } else {
                remove(plus.getAttributes(), "_autoremap");
            }
            return;
        }
        for (Attribute attribute : attributes) {
            if (!attribute.getName().equals("name")) {
                attribute.setValue(attribute.getValue().substring(1, attribute.getValue().length() - 1));
            }
        }
    }

    private static void precondition(TreeNode node, Map<EObject, EObject> replacements) {
        BlackboardChecks.Check check = BlackboardChecks.fromCondition(node.attribute("if"));
        TreeNode result = become(node, (EClass) BtPackage.eINSTANCE.getEClassifier(check.tag), check.tag, replacements);
        List<Attribute> attributes = result.getAttributes();
        Attribute condition = BtAttributes.find(attributes, "if");
        condition.setName("value_A");
        condition.setValue(check.valueA);
        attributes.add(attributes.indexOf(condition) + 1, attribute("value_B", check.valueB));
        rename(attributes, "else", "return_on_mismatch");
    }
}
