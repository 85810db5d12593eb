package org.miron.bt.formats;

import static org.miron.bt.formats.TreeEdits.*;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Subtree;
import org.miron.bt.bt.SubtreePlus;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtTrees;
import org.miron.bt.validation.BtIssueCodes;
import org.miron.bt.validation.BtVersions;

/**
 * Version 3 to 4, as BehaviorTree.CPP's convert_v3_to_v4.py does (SequenceStar, SubTree ports in
 * braces, __shared_blackboard, SubTreePlus) plus what it leaves out: explicit Control IDs, the
 * RetryUntilSuccesful spelling, Parallel's port names, BlackboardCheck* as Precondition, a tree
 * used as a tag as an explicit SubTree, explicit leaves under a ReactiveSequence in the compact form
 * (BT.CPP 4 rejects the explicit one there).
 */
final class V3ToV4 {
    private V3ToV4() {
    }

    static void check(TreeNode node, List<ConversionProblem> problems) {
        String tag = node.getTag();
        if ("FallbackStar".equals(tag)) {
            problems.add(new ConversionProblem(node, "FallbackStar has no BehaviorTree.CPP 4 equivalent "
                    + "(BehaviorTree.CPP 3 does not register it either): write Fallback or ReactiveFallback",
                    BtIssueCodes.NO_V4_EQUIVALENT));
        } else if (tag != null && tag.startsWith("BlackboardCheck")) {
            for (String port : List.of("value_A", "value_B")) {
                String value = node.attribute(port);
                if (value == null || BlackboardChecks.operand(tag, value) == null) {
                    problems.add(new ConversionProblem(node, tag + " " + port + " '" + value
                            + "' has no BehaviorTree.CPP 4 equivalent in a Precondition script",
                            BtIssueCodes.NO_V4_EQUIVALENT));
                }
            }
        }
        for (Attribute attribute : node.getAttributes()) {
            if (BtVersions.SCRIPT_DIRECTIVES.contains(attribute.getName())) {
                problems.add(new ConversionProblem(attribute, "attribute " + attribute.getName()
                        + " is reserved for scripts in BehaviorTree.CPP 4: rename the port first",
                        BtIssueCodes.NO_V4_EQUIVALENT));
            }
        }
    }

    static void apply(TreeNode node, Map<EObject, EObject> replacements) {
        String tag = node.getTag();
        if ("SequenceStar".equals(tag)) {
            node.setTag("SequenceWithMemory");
        } else if ("RetryUntilSuccesful".equals(tag)) {
            node.setTag("RetryUntilSuccessful");
        } else if ("Control".equals(tag) && "SequenceStar".equals(node.attribute("ID"))) {
            set(node.getAttributes(), "ID", "SequenceWithMemory");
        } else if (node instanceof Parallel && "Parallel".equals(tag)) {
            for (Map.Entry<String, String> port : BtVersions.PARALLEL_PORTS.entrySet()) {
                rename(node.getAttributes(), port.getKey(), port.getValue());
            }
        } else if (node instanceof Subtree) {
            subtree(node, replacements);
        } else if (node instanceof SubtreePlus) {
            subtreePlus(node, replacements);
        } else if (tag != null && tag.startsWith("BlackboardCheck")) {
            blackboardCheck(node, replacements);
        } else if (("Action".equals(tag) || "Condition".equals(tag)) && node.attribute("ID") != null
                && node.eContainer() instanceof TreeNode
                && "ReactiveSequence".equals(((TreeNode) node.eContainer()).getTag())) {
            // BT.CPP 4 looks ReactiveSequence's children up by element name: the compact form loads.
            String id = remove(node.getAttributes(), "ID");
            become(node, BtPackage.Literals.ACTION, id, replacements);
        } else if (BtTrees.isCompactSubtree(node)) {
            // <Tree/> for <SubTree ID="Tree"/>: version 4 only knows the explicit form.
            BehaviorTree tree = BtTrees.visibleTreesOf(node).get(tag);
            TreeNode subtree = become(node, BtPackage.Literals.SUBTREE, "SubTree", replacements);
            ((Subtree) subtree).setBehaviorTree(tree);
            subtree(subtree, replacements);
        }
    }

    /** v3 SubTree ports name the parent's key; v4 writes the key in braces. __shared_blackboard becomes _autoremap. */
    private static void subtree(TreeNode node, Map<EObject, EObject> replacements) {
        for (Attribute attribute : List.copyOf(node.getAttributes())) {
            String name = attribute.getName();
            if (name.equals("__shared_blackboard")) {
                if (BtVersions.BOOLEANS.contains(attribute.getValue()) && isTrue(attribute.getValue())) {
                    attribute.setName("_autoremap");
                    attribute.setValue("true");
                } else {
                    node.getAttributes().remove(attribute);
                }
            } else if (!name.equals("name") && !TreeEdits.isRemap(attribute.getValue())) {
                attribute.setValue("{" + attribute.getValue() + "}");
            }
        }
    }

    /**
     * SubTreePlus is v4's SubTree: ports as written, __autoremap renamed. Without __autoremap it
     * says _autoremap="false" (the default), which tells SubTreePlus from SubTree on the way back.
     */
    private static void subtreePlus(TreeNode node, Map<EObject, EObject> replacements) {
        TreeNode subtree = become(node, BtPackage.Literals.SUBTREE, "SubTree", replacements);
        remove(subtree.getAttributes(), "__shared_blackboard"); // no meaning on SubTreePlus
        if (subtree.attribute("__autoremap") == null) {
            subtree.getAttributes().add(attribute("_autoremap", "false"));
        } else {
            rename(subtree.getAttributes(), "__autoremap", "_autoremap");
        }
    }

    private static void blackboardCheck(TreeNode node, Map<EObject, EObject> replacements) {
        String tag = node.getTag();
        String condition = BlackboardChecks.operand(tag, node.attribute("value_A")) + " == "
                + BlackboardChecks.operand(tag, node.attribute("value_B"));
        TreeNode precondition = become(node, BtPackage.Literals.PRECONDITION, "Precondition", replacements);
        List<Attribute> attributes = precondition.getAttributes();
        Attribute a = org.miron.bt.util.BtAttributes.find(attributes, "value_A");
        a.setName("if");
        a.setValue(condition);
        remove(attributes, "value_B");
        rename(attributes, "return_on_mismatch", "else");
        // Groot writes unset ports empty; version 3 then returns FAILURE, version 4 would fail to
        // read else="" on every tick: leave it out, FAILURE is v4's default too.
        if ("".equals(precondition.attribute("else"))) {
            remove(attributes, "else");
        }
    }

    static boolean isTrue(String value) {
        return value.equals("true") || value.equals("True") || value.equals("TRUE") || value.equals("1");
    }
}
