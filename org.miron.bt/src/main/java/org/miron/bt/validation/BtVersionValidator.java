package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;

/**
 * A file's version comes from BTCPP_format on its root (absent: 3). Elements and attributes of
 * the other version are errors naming what to write instead (issue data: the replacement).
 * Composed into BtValidator.
 */
public class BtVersionValidator extends AbstractDeclarativeValidator {

    private static final BtPackage BT = BtPackage.eINSTANCE;

    @Override
    public void register(EValidatorRegistrar registrar) {
        // Runs as part of BtValidator (@ComposedChecks), not on its own.
    }

    @Override
    protected java.util.List<EPackage> getEPackages() {
        return java.util.List.of(BT);
    }

    @Check
    public void checkFormat(BTModel model) {
        String format = model.getBTCPP_format();
        if (format != null && !format.trim().equals("3") && !format.trim().equals("4")) {
            error("BTCPP_format must be 3 or 4, not '" + format + "'",
                    BtAttributes.find(model.getAttributes(), BtFormats.ATTRIBUTE), BT.getAttribute_Value(),
                    UNSUPPORTED_FORMAT, "4");
        }
    }

    @Check
    public void checkElementVersion(TreeNode node) {
        String tag = node.getTag();
        if (tag == null) {
            return;
        }
        int version = BtFormats.versionOf(node);
        if (version == 4 && BtTrees.isCompactSubtree(node)) {
            error("<" + tag + "/> names a tree, which only BehaviorTree.CPP 3 accepts: write <SubTree ID=\"" + tag
                    + "\"/>", node, BT.getTreeNode_Tag(), V3_ONLY_ELEMENT, "SubTree");
        } else if (version == 4 && BtVersions.V3_ONLY_TAGS.containsKey(tag)) {
            String replacement = BtVersions.V3_ONLY_TAGS.get(tag);
            error(tag + " is not a BehaviorTree.CPP 4 node: " + v4Advice(tag, replacement), node,
                    BT.getTreeNode_Tag(), V3_ONLY_ELEMENT, replacement);
        } else if (version == 3 && BtVersions.V4_ONLY_TAGS.containsKey(tag)) {
            String replacement = BtVersions.V4_ONLY_TAGS.get(tag);
            String advice = replacement.isEmpty() ? "version 3 has no equivalent; set BTCPP_format=\"4\" on <root>"
                    : "write " + replacement + " in version 3, or set BTCPP_format=\"4\" on <root>";
            // A warning: version 3 loads any tag as a node the application registered (the corpus'
            // tests__gtest_reactive__L40.xml registers its own Sleep), so only the intent is in doubt.
            warning(tag + " is a BehaviorTree.CPP 4 node: " + advice, node, BT.getTreeNode_Tag(), V4_ONLY_ELEMENT,
                    replacement.isEmpty() ? new String[0] : new String[] { replacement });
        }
    }

    /** BT.CPP 4 checks ReactiveSequence's children by element name, so explicit forms fail to load there. */
    @Check
    public void checkReactiveChild(TreeNode node) {
        if (BtFormats.versionOf(node) == 4 && BtTrees.isExplicitForm(node) && node.attribute("ID") != null
                && node.eContainer() instanceof TreeNode
                && "ReactiveSequence".equals(((TreeNode) node.eContainer()).getTag())) {
            String id = node.attribute("ID");
            error("BehaviorTree.CPP 4 does not load <" + node.getTag() + " ID=\"" + id
                    + "\"> directly under a ReactiveSequence: write <" + id + "/>", node, BT.getTreeNode_Tag(),
                    REACTIVE_EXPLICIT_CHILD, id);
        }
    }

    private static String v4Advice(String tag, String replacement) {
        switch (replacement) {
        case "SubTree":
            return "write <SubTree> (ports remapped with port=\"{key}\", _autoremap=\"true\" for the others)";
        case "Precondition":
            return "write <Precondition if=\"value_A == value_B\" else=\"...\"> (or a ScriptCondition)";
        case "Fallback":
            return "write Fallback (or ReactiveFallback)";
        default:
            return "write " + replacement;
        }
    }

    @Check
    public void checkAttributeVersion(TreeNode node) {
        int version = BtFormats.versionOf(node);
        for (Attribute attribute : node.getAttributes()) {
            String name = attribute.getName();
            if (version == 4) {
                if (node instanceof SubtreeNode && name.equals("__shared_blackboard")) {
                    error("__shared_blackboard is BehaviorTree.CPP 3 (version 4 ignores it): write _autoremap=\"true\"",
                            attribute, BT.getAttribute_Name(), V3_ONLY_ATTRIBUTE, "_autoremap");
                } else if (isParallel(node) && BtVersions.PARALLEL_PORTS.containsKey(name)) {
                    error(name + " is the BehaviorTree.CPP 3 name of this port: write "
                            + BtVersions.PARALLEL_PORTS.get(name), attribute, BT.getAttribute_Name(),
                            V3_ONLY_ATTRIBUTE, BtVersions.PARALLEL_PORTS.get(name));
                }
            } else if (version == 3) {
                if (BtVersions.SCRIPT_DIRECTIVES.contains(name)) {
                    error(name + " is a BehaviorTree.CPP 4 pre/post-condition: set BTCPP_format=\"4\" on <root>",
                            attribute, BT.getAttribute_Name(), V4_ONLY_ATTRIBUTE);
                } else if (node instanceof SubtreeNode && name.equals("_autoremap")) {
                    error("_autoremap is BehaviorTree.CPP 4: in version 3 write <SubTreePlus __autoremap=\"true\">",
                            attribute, BT.getAttribute_Name(), V4_ONLY_ATTRIBUTE, "__autoremap");
                } else if (attribute.getValue().equals("{=}")) {
                    error(name + "=\"{=}\" is BehaviorTree.CPP 4 shorthand: write " + name + "=\"{" + name + "}\"",
                            attribute, BT.getAttribute_Value(), V4_ONLY_ATTRIBUTE, "{" + name + "}");
                } else if (isParallel(node) && BtVersions.PARALLEL_PORTS.containsValue(name)) {
                    String v3 = name.replace("_count", "_threshold");
                    error(name + " is the BehaviorTree.CPP 4 name of this port: write " + v3 + " in version 3",
                            attribute, BT.getAttribute_Name(), V4_ONLY_ATTRIBUTE, v3);
                }
            }
        }
    }

    private static boolean isParallel(TreeNode node) {
        return node instanceof Parallel && "Parallel".equals(node.getTag());
    }
}
