package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.ComposedChecks;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BlackboardCheckDouble;
import org.miron.bt.bt.BlackboardCheckInt;
import org.miron.bt.bt.BlackboardCheckString;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.Condition;
import org.miron.bt.bt.CustomControl;
import org.miron.bt.bt.Delay;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.FallbackStar;
import org.miron.bt.bt.IfThenElse;
import org.miron.bt.bt.Import;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Repeat;
import org.miron.bt.bt.RetryUntilSuccess;
import org.miron.bt.bt.SetBlackboard;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.Timeout;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.bt.WhileDoElse;
import org.miron.bt.scoping.BtGlobalScopeProvider;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtCloseTags;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;
import org.miron.bt.util.Suggestions;

/**
 * The rules BehaviorTree.CPP 3 applies when it loads or ticks a tree, checked up front so a user
 * sees every mistake with its position. Where a file is valid but will not load in current
 * BehaviorTree.CPP 3 releases, a warning says what to write instead.
 */
@ComposedChecks(validators = { BtVersionValidator.class, BtV4Validator.class })
public class BtValidator extends AbstractBtValidator {

    private static final BtPackage BT = BtPackage.eINSTANCE;

    @Check
    public void checkMainTree(BTModel model) {
        String main = model.getMain_tree_to_execute();
        Map<String, BehaviorTree> visible = BtTrees.visibleTrees(model.eResource());
        if (main == null) {
            // Only the file BehaviorTree.CPP loads first needs it; included files are libraries.
            if (model.getTrees().size() > 1 && !BtTrees.isIncludedByAnother(model.eResource())) {
                error("main_tree_to_execute is required when a file holds several trees ("
                        + model.getTrees().size() + " here)", model, null, MAIN_TREE_REQUIRED);
            }
        } else if (!visible.containsKey(main)) {
            error("main_tree_to_execute '" + main + "' names no BehaviorTree of this file or its includes",
                    attribute(model.getAttributes(), "main_tree_to_execute"), BT.getAttribute_Value(),
                    UNKNOWN_MAIN_TREE, Suggestions.closest(main, visible.keySet()).toArray(new String[0]));
        }
    }

    @Check
    public void checkInclude(Import include) {
        URI uri = BtGlobalScopeProvider.resolve(include.eResource(), include.getImportURI());
        if (uri == null || !EcoreUtil2.isValidUri(include, uri)) {
            error("included file '" + include.getImportURI() + "' not found (paths are relative to this file)",
                    include, BT.getImport_ImportURI(), INCLUDE_NOT_FOUND);
        } else if (uri.equals(include.eResource().getURI())) {
            error("a file cannot include itself", include, BT.getImport_ImportURI(), SELF_INCLUDE);
        }
    }

    @Check
    public void checkTree(BehaviorTree tree) {
        if (tree.getName() == null || tree.getName().isEmpty()) {
            error("BehaviorTree needs an ID attribute", tree, null, TREE_WITHOUT_ID);
        } else {
            checkDuplicateTree(tree);
        }
        if (tree.getNodes().isEmpty()) {
            error("BehaviorTree '" + tree.getName() + "' must have exactly one root node, it has none", tree, null,
                    TREE_WITHOUT_ROOT);
        }
        for (int i = 1; i < tree.getNodes().size(); i++) {
            error("BehaviorTree '" + tree.getName() + "' must have exactly one root node: wrap its "
                    + tree.getNodes().size() + " nodes in a Sequence or another control node",
                    tree.getNodes().get(i), null, TREE_SEVERAL_ROOTS);
        }
    }

    private void checkDuplicateTree(BehaviorTree tree) {
        BTModel model = (BTModel) tree.eContainer();
        for (BehaviorTree other : model.getTrees()) {
            if (other == tree) {
                break;
            }
            if (tree.getName().equals(other.getName())) {
                error("duplicate BehaviorTree ID '" + tree.getName() + "'", tree, BT.getBehaviorTree_Name(),
                        DUPLICATE_TREE_ID);
                return;
            }
        }
        for (Resource included : BtTrees.includedResources(tree.eResource())) {
            for (BehaviorTree other : BtTrees.treesOf(included)) {
                if (tree.getName().equals(other.getName())) {
                    error("duplicate BehaviorTree ID '" + tree.getName() + "': also defined in "
                            + included.getURI().lastSegment(), tree, BT.getBehaviorTree_Name(), DUPLICATE_TREE_ID);
                    return;
                }
            }
        }
    }

    @Check
    public void checkControlChildren(ControlNode node) {
        if (node.getNodes().isEmpty() && !isConditional(node)) {
            error(node.getTag() + " needs at least one child", node, BT.getTreeNode_Tag(), CONTROL_WITHOUT_CHILDREN);
        }
    }

    private static boolean isConditional(ControlNode node) {
        return node instanceof IfThenElse || node instanceof WhileDoElse;
    }

    /** IfThenElse and WhileDoElse: a condition, a then-branch and an optional else-branch. */
    @Check
    public void checkConditional(ControlNode node) {
        if (!isConditional(node)) {
            return;
        }
        int children = node.getNodes().size();
        if (children < 2) {
            error(node.getTag() + " needs 2 or 3 children (condition, then, optional else), it has " + children,
                    node, BT.getTreeNode_Tag(), CONDITIONAL_CHILD_COUNT);
        } else if (children > 3) {
            error(node.getTag() + " needs 2 or 3 children (condition, then, optional else), it has " + children,
                    node.getNodes().get(3), null, CONDITIONAL_CHILD_COUNT);
        }
    }

    @Check
    public void checkDecoratorChild(DecoratorNode node) {
        if (node.getNode() == null) {
            error(node.getTag() + " needs exactly one child, it has none", node, BT.getTreeNode_Tag(),
                    DECORATOR_CHILD_COUNT);
        } else if (!node.getSurplus().isEmpty()) {
            error(node.getTag() + " needs exactly one child, it has " + (1 + node.getSurplus().size()),
                    node.getSurplus().get(0), null, DECORATOR_CHILD_COUNT);
        }
    }

    @Check
    public void checkParallel(Parallel node) {
        if (BtFormats.versionOf(node) != 3 || "ParallelAll".equals(node.getTag())) {
            return; // BtV4Validator; ParallelAll is an error in version 3
        }
        int children = node.getNodes().size();
        Integer success = checkInteger(node, "success_threshold", true, Integer.MIN_VALUE);
        Integer failure = checkInteger(node, "failure_threshold", false, Integer.MIN_VALUE);
        checkThreshold(node, "success_threshold", success, children);
        checkThreshold(node, "failure_threshold", failure, children);
    }

    private void checkThreshold(Parallel node, String port, Integer value, int children) {
        // Negative thresholds count from the number of children (-1 = all), as in BehaviorTree.CPP.
        if (value != null && children > 0 && (value > children || value < -children || value == 0)) {
            error(port + " " + value + " does not fit a Parallel with " + children + " children",
                    attribute(node.getAttributes(), port), BT.getAttribute_Value(), PARALLEL_THRESHOLD);
        }
    }

    @Check
    public void checkSwitch(Switch node) {
        int cases = Integer.parseInt(node.getTag().substring("Switch".length()));
        if (node.attribute("variable") == null) {
            error(node.getTag() + " needs a variable attribute, e.g. variable=\"{choice}\"", node, BT.getTreeNode_Tag(),
                    SWITCH_WITHOUT_VARIABLE);
        }
        for (int k = 1; k <= cases; k++) {
            if (node.attribute("case_" + k) == null) {
                error(node.getTag() + " needs attribute case_" + k, node, BT.getTreeNode_Tag(), SWITCH_MISSING_CASE,
                        "case_" + k);
            }
        }
        for (Attribute attribute : node.getAttributes()) {
            String name = attribute.getName();
            if (name.startsWith("case_") && !isCaseOf(name, cases)) {
                error(node.getTag() + " has only " + cases + " cases: " + name + " is not one of case_1..case_"
                        + cases, attribute, BT.getAttribute_Name(), SWITCH_EXTRA_CASE, name);
            }
        }
        if (!node.getNodes().isEmpty() && node.getNodes().size() != cases + 1) {
            error(node.getTag() + " with " + cases + " cases needs " + (cases + 1)
                    + " children (one per case and a default last), it has " + node.getNodes().size(),
                    node, BT.getTreeNode_Tag(), SWITCH_CHILD_COUNT);
        }
    }

    private static boolean isCaseOf(String name, int cases) {
        try {
            int k = Integer.parseInt(name.substring("case_".length()));
            return k >= 1 && k <= cases;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    @Check
    public void checkRepeat(Repeat node) {
        checkInteger(node, "num_cycles", true, -1);
    }

    @Check
    public void checkRetry(RetryUntilSuccess node) {
        checkInteger(node, "num_attempts", true, -1);
        if ("RetryUntilSuccesful".equals(node.getTag()) && BtFormats.versionOf(node) == 3) {
            warning("RetryUntilSuccesful is the BehaviorTree.CPP 3.5-3.6 spelling; 3.7 and later only load "
                    + "RetryUntilSuccessful", node, BT.getTreeNode_Tag(), RETRY_OLD_SPELLING,
                    "RetryUntilSuccessful");
        }
    }

    @Check
    public void checkTimeout(Timeout node) {
        checkInteger(node, "msec", true, 0);
    }

    @Check
    public void checkDelay(Delay node) {
        checkInteger(node, "delay_msec", true, 0);
        if (BtFormats.versionOf(node) == 3) {
            warning("Delay needs BehaviorTree.CPP 3.8 or later; earlier 3.x releases do not register it", node,
                    BT.getTreeNode_Tag(), DELAY_NEEDS_3_8);
        }
    }

    @Check
    public void checkFallbackStar(FallbackStar node) {
        if (BtFormats.versionOf(node) != 3) {
            return; // an error there (BtVersionValidator)
        }
        warning("FallbackStar is not registered in BehaviorTree.CPP 3; write Fallback (or ReactiveFallback) "
                + "for files that must load there", node, BT.getTreeNode_Tag(), FALLBACK_STAR,
                "Fallback", "ReactiveFallback");
    }

    @Check
    public void checkBlackboardCheck(DecoratorNode node) {
        if (node instanceof BlackboardCheckInt || node instanceof BlackboardCheckDouble
                || node instanceof BlackboardCheckString) {
            requireAttribute(node, "value_A");
            requireAttribute(node, "value_B");
            String mismatch = node.attribute("return_on_mismatch");
            if (mismatch != null && !isBlackboardPointer(mismatch)
                    && !Set.of("SUCCESS", "FAILURE", "RUNNING").contains(mismatch)) {
                error("return_on_mismatch must be SUCCESS, FAILURE or RUNNING, not '" + mismatch + "'",
                        attribute(node.getAttributes(), "return_on_mismatch"), BT.getAttribute_Value(),
                        BAD_RETURN_ON_MISMATCH);
            }
        }
    }

    @Check
    public void checkSetBlackboard(SetBlackboard node) {
        requireAttribute(node, "value");
        requireAttribute(node, "output_key");
    }

    /** Explicit forms name the registered node by ID: Action, Condition, Control, Decorator. */
    @Check
    public void checkRegisteredId(TreeNode node) {
        boolean explicit = "Action".equals(node.getTag()) || node instanceof Condition
                || "Control".equals(node.getTag()) || "Decorator".equals(node.getTag());
        if (explicit && node.attribute("ID") == null) {
            error(node.getTag() + " needs an ID attribute naming the registered node", node, BT.getTreeNode_Tag(),
                    NODE_WITHOUT_ID);
        }
    }

    @Check
    public void checkSubtreeId(SubtreeNode node) {
        if (node.getBehaviorTree() == null && !hasIdNode(node)) {
            error(node.getTag() + " needs an ID attribute naming a BehaviorTree", node, BT.getTreeNode_Tag(),
                    SUBTREE_WITHOUT_ID);
        }
    }

    private static boolean hasIdNode(SubtreeNode node) {
        return !org.eclipse.xtext.nodemodel.util.NodeModelUtils
                .findNodesForFeature(node, BT.getSubtreeNode_BehaviorTree()).isEmpty();
    }

    @Check
    public void checkCompactAction(org.miron.bt.bt.Action node) {
        if ("Action".equals(node.getTag()) || node.getTag() == null) {
            return;
        }
        BTModel model = EcoreUtil2.getContainerOfType(node, BTModel.class);
        if (model.getNodesmodel() == null || BtTrees.visibleTrees(node.eResource()).containsKey(node.getTag())) {
            return;
        }
        if (!BtTrees.declaredNodeIds(model.getNodesmodel()).contains(node.getTag())) {
            warning("<" + node.getTag() + "/> is neither a BehaviorTree nor declared in TreeNodesModel; "
                    + "it must be registered in the executor", node, BT.getTreeNode_Tag(), UNDECLARED_NODE,
                    node.getTag());
        }
    }

    /**
     * A compact element with children, {@code <RateController hz="1">...</RateController>}: its ID
     * should be declared, and a node declared as an Action or a Condition takes no children, one
     * declared as a Decorator exactly one.
     */
    @Check
    public void checkCompactControl(CustomControl node) {
        if ("Control".equals(node.getTag()) || node.getTag() == null) {
            return;
        }
        BTModel model = EcoreUtil2.getContainerOfType(node, BTModel.class);
        if (model.getNodesmodel() == null) {
            return;
        }
        String kind = BtTrees.declaredNodeKinds(model.getNodesmodel()).get(node.getTag());
        int children = node.getNodes().size();
        if (kind == null) {
            warning("<" + node.getTag() + "> is not declared in TreeNodesModel; it must be registered in the "
                    + "executor as a control node", node, BT.getTreeNode_Tag(), UNDECLARED_NODE,
                    node.getTag());
        } else if (kind.equals("Decorator") && children != 1) {
            error("<" + node.getTag() + "> is declared as a Decorator in TreeNodesModel and needs exactly one child, it has "
                    + children, node.getNodes().get(1), null, DECORATOR_CHILD_COUNT);
        } else if (kind.equals("Action") || kind.equals("Condition")) {
            error("<" + node.getTag() + "> is declared as " + (kind.equals("Action") ? "an " : "a ") + kind
                    + " in TreeNodesModel and cannot have children", node, BT.getTreeNode_Tag(),
                    LEAF_WITH_CHILDREN);
        }
    }

    /** {@code <GoTo></GoTo>}, {@code <Rate>...</Rate>}: the grammar cannot require equal names, so this does. */
    @Check
    public void checkClosingName(TreeNode node) {
        ILeafNode closing = BtCloseTags.closingName(node);
        if (closing != null && !closing.getText().equals(node.getTag())) {
            acceptError("</" + closing.getText() + "> does not close <" + node.getTag() + ">: write </" + node.getTag()
                    + ">", node, closing.getOffset(), closing.getLength(), CLOSE_TAG_MISMATCH, node.getTag());
        }
    }

    @Check
    public void checkDuplicateAttributes(TreeNode node) {
        Map<String, Attribute> seen = new HashMap<>();
        for (Attribute attribute : node.getAttributes()) {
            if (seen.putIfAbsent(attribute.getName(), attribute) != null) {
                error("attribute " + attribute.getName() + " is written twice", attribute, BT.getAttribute_Name(),
                        DUPLICATE_ATTRIBUTE, attribute.getName());
            }
        }
    }

    /** Checks an integer port; a blackboard pointer {key} is read at tick time and accepted. */
    private Integer checkInteger(TreeNode node, String port, boolean required, int min) {
        Attribute attribute = attribute(node.getAttributes(), port);
        if (attribute == null) {
            if (required) {
                error(node.getTag() + " needs attribute " + port, node, BT.getTreeNode_Tag(), MISSING_ATTRIBUTE, port);
            }
            return null;
        }
        String value = attribute.getValue().trim();
        if (isBlackboardPointer(value)) {
            return null;
        }
        try {
            int number = Integer.parseInt(value);
            if (number < min) {
                error(port + " must be at least " + min + ", not " + number, attribute, BT.getAttribute_Value(),
                        INTEGER_TOO_SMALL, String.valueOf(min));
            }
            return number;
        } catch (NumberFormatException e) {
            error(port + " must be an integer, not '" + attribute.getValue() + "'", attribute, BT.getAttribute_Value(),
                    NOT_AN_INTEGER);
            return null;
        }
    }

    private void requireAttribute(TreeNode node, String name) {
        if (node.attribute(name) == null) {
            error(node.getTag() + " needs attribute " + name, node, BT.getTreeNode_Tag(), MISSING_ATTRIBUTE, name);
        }
    }

    private static boolean isBlackboardPointer(String value) {
        return (value.startsWith("{") || value.startsWith("${")) && value.endsWith("}");
    }

    private static Attribute attribute(List<Attribute> attributes, String name) {
        return BtAttributes.find(attributes, name);
    }
}
