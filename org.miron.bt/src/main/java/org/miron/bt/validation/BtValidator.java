package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.ComposedChecks;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.CustomControl;
import org.miron.bt.bt.Delay;
import org.miron.bt.bt.FallbackStar;
import org.miron.bt.bt.ForeignElement;
import org.miron.bt.bt.Import;
import org.miron.bt.bt.LeafNode;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.RetryUntilSuccess;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.resource.BtXmlFiles;
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
@ComposedChecks(validators = { BtVersionValidator.class, BtV4Validator.class, BtBuiltinValidator.class,
        BtKeyValidator.class })
public class BtValidator extends AbstractBtValidator {

    private static final BtPackage BT = BtPackage.eINSTANCE;

    @Check
    public void checkMainTree(BTModel model) {
        String main = model.getMain_tree_to_execute();
        Map<String, BehaviorTree> visible = BtTrees.visibleTrees(model.eResource());
        // Without it, a file with several trees is an include library: only what runs a file (the
        // executor, the weaver) needs its main tree, so a file's verdict never depends on which
        // other files are loaded with it.
        if (main != null && !visible.containsKey(main)) {
            error("main_tree_to_execute '" + main + "' names no BehaviorTree of this file or its includes",
                    attribute(model.getAttributes(), "main_tree_to_execute"), BT.getAttribute_Value(),
                    UNKNOWN_MAIN_TREE, Suggestions.closest(main, visible.keySet()).toArray(new String[0]));
        }
    }

    /** BehaviorTree.CPP 3: "Only a single node <TreeNodesModel> is supported" (the model keeps the last). */
    @Check
    public void checkSingleNodesModel(BTModel model) {
        List<org.eclipse.xtext.nodemodel.INode> written = org.eclipse.xtext.nodemodel.util.NodeModelUtils
                .findNodesForFeature(model, BT.getBTModel_Nodesmodel());
        for (int i = 1; i < written.size(); i++) {
            acceptError("only one <TreeNodesModel> is allowed under <root>: merge the declarations", model,
                    written.get(i).getOffset(), "<TreeNodesModel>".length(), DUPLICATE_NODES_MODEL);
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
        } else if (!BtXmlFiles.isTree(EcoreUtil2.getResource(include.eResource(), uri.toString()))) {
            error("included file '" + include.getImportURI() + "' is not a behaviour-tree file (its root element "
                    + "must be <root>)", include, BT.getImport_ImportURI(), INCLUDE_NOT_BT);
        }
    }

    /** BehaviorTree.CPP reads include, BehaviorTree and TreeNodesModel under root, and skips anything else. */
    @Check
    public void checkForeignElement(ForeignElement element) {
        if (element.eContainer() instanceof BTModel) {
            List<String> closest = Suggestions.closest(element.getTag(), List.of("include", "BehaviorTree",
                    "TreeNodesModel"));
            warning("<" + element.getTag() + "> is not read by BehaviorTree.CPP, which ignores it"
                    + (closest.isEmpty() ? "" : ": did you mean <" + closest.get(0) + ">?"), element,
                    BT.getForeignElement_Tag(), UNKNOWN_ELEMENT, closest.toArray(new String[0]));
        }
        ILeafNode closing = BtCloseTags.closingName(element);
        if (closing != null && !closing.getText().equals(element.getTag())) {
            acceptError("</" + closing.getText() + "> does not close <" + element.getTag() + ">: write </"
                    + element.getTag() + ">", element, closing.getOffset(), closing.getLength(), CLOSE_TAG_MISMATCH,
                    element.getTag());
        }
    }

    @Check
    public void checkTree(BehaviorTree tree) {
        if (tree.getName() == null || tree.getName().isEmpty()) {
            // A file's only tree is its main tree, as in BehaviorTree.CPP 3; among several, nothing
            // can name it (BehaviorTree.CPP loads it under a generated name).
            if (((BTModel) tree.eContainer()).getTrees().size() > 1) {
                warning("a BehaviorTree without ID cannot be referenced or named as main_tree_to_execute when the "
                        + "file holds several trees: give it an ID", tree, null, TREE_WITHOUT_ID);
            }
        } else {
            checkDuplicateTree(tree);
        }
        String name = BtTrees.displayName(tree);
        if (tree.getNodes().isEmpty()) {
            error(name + " must have exactly one root node, it has none", tree, null,
                    TREE_WITHOUT_ROOT);
        }
        for (int i = 1; i < tree.getNodes().size(); i++) {
            error(name + " must have exactly one root node: wrap its "
                    + tree.getNodes().size() + " nodes in a Sequence or another control node",
                    tree.getNodes().get(i), null, TREE_SEVERAL_ROOTS);
        }
    }

    /**
     * BehaviorTree.CPP 3 keeps the first of two trees with one ID. A second tree with the same
     * content (whitespace and comments aside) is harmless and only warned about; references
     * resolve to the first (BtResourceDescriptionStrategy does not export it). A different one is
     * an error: which of the two a reader means cannot be told.
     */
    private void checkDuplicateTree(BehaviorTree tree) {
        BTModel model = (BTModel) tree.eContainer();
        for (BehaviorTree other : model.getTrees()) {
            if (other == tree) {
                break;
            }
            if (tree.getName().equals(other.getName())) {
                reportDuplicate(tree, other, "");
                return;
            }
        }
        for (Resource included : BtTrees.includedResources(tree.eResource())) {
            for (BehaviorTree other : BtTrees.treesOf(included)) {
                if (tree.getName().equals(other.getName())) {
                    reportDuplicate(tree, other, ": also defined in " + included.getURI().lastSegment());
                    return;
                }
            }
        }
    }

    private void reportDuplicate(BehaviorTree tree, BehaviorTree first, String where) {
        if (BtTrees.sameContent(tree, first)) {
            warning("BehaviorTree '" + tree.getName() + "' is defined twice with the same content" + where
                    + "; the first one is used", tree, BT.getBehaviorTree_Name(), DUPLICATE_IDENTICAL_TREE);
        } else {
            error("duplicate BehaviorTree ID '" + tree.getName() + "'" + where, tree, BT.getBehaviorTree_Name(),
                    DUPLICATE_TREE_ID);
        }
    }

    /**
     * Children inside a leaf: BehaviorTree.CPP rejects them in Action and Condition, and loads
     * the built-in leaves while dropping them, which is never what the author meant.
     */
    @Check
    public void checkLeafChildren(LeafNode node) {
        if (node.getSurplus().isEmpty()) {
            return;
        }
        String article = "Action".equals(node.getTag()) || "AlwaysSuccess".equals(node.getTag())
                || "AlwaysFailure".equals(node.getTag()) ? "an " : "a ";
        if (BtTrees.isExplicitForm(node)) {
            error(article + node.getTag() + " cannot have children", node.getSurplus().get(0), null,
                    LEAF_WITH_CHILDREN);
        } else {
            warning(article + node.getTag() + " cannot have children: BehaviorTree.CPP 3 ignores them",
                    node.getSurplus().get(0), null, LEAF_WITH_CHILDREN);
        }
    }

    @Check
    public void checkParallel(Parallel node) {
        if (BtFormats.versionOf(node) != 3 || "ParallelAll".equals(node.getTag())) {
            return; // BtV4Validator; ParallelAll is an error in version 3
        }
        checkThreshold(node, BuiltinNodes.SUCCESS_THRESHOLD);
        checkThreshold(node, BuiltinNodes.FAILURE_THRESHOLD);
    }

    /** Whether a literal threshold fits the children (BtBuiltinValidator reports one that is no integer). */
    private void checkThreshold(Parallel node, String port) {
        Attribute attribute = attribute(node.getAttributes(), port);
        Integer value = attribute == null ? null : literalInteger(attribute.getValue());
        int children = node.getNodes().size();
        // Negative thresholds count from the number of children (-1 = all), as in BehaviorTree.CPP.
        if (value != null && children > 0 && (value > children || value < -children || value == 0)) {
            error(port + " " + value + " does not fit a Parallel with " + children + " children", attribute,
                    BT.getAttribute_Value(), PARALLEL_THRESHOLD);
        }
    }

    /** A literal integer, or null for a blackboard pointer or a value that is not one. */
    static Integer literalInteger(String value) {
        try {
            return Integer.parseInt(value.trim());
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** case_k beyond N (the required ports and the N+1 children are BtBuiltinValidator's, from the catalogue). */
    @Check
    public void checkSwitch(Switch node) {
        int cases = NodeCatalogue.require(node.getTag()).children().min() - 1;
        for (Attribute attribute : node.getAttributes()) {
            String name = attribute.getName();
            if (name.startsWith(BuiltinNodes.CASE_PREFIX) && !isCaseOf(name, cases)) {
                error(node.getTag() + " has only " + cases + " cases: " + name + " is not one of case_1..case_"
                        + cases, attribute, BT.getAttribute_Name(), SWITCH_EXTRA_CASE, name);
            }
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
    public void checkRetry(RetryUntilSuccess node) {
        String tag = NodeCatalogue.require(node.getTag()).tag(); // the spelling of 3.7 and later
        if (!tag.equals(node.getTag()) && BtFormats.versionOf(node) == 3) {
            warning(node.getTag() + " is the BehaviorTree.CPP 3.5-3.6 spelling; 3.7 and later only load " + tag, node,
                    BT.getTreeNode_Tag(), RETRY_OLD_SPELLING, tag);
        }
    }

    @Check
    public void checkDelay(Delay node) {
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

    /** Explicit forms name the registered node by ID: Action, Condition, Control, Decorator. */
    @Check
    public void checkRegisteredId(TreeNode node) {
        if (BtTrees.isExplicitForm(node) && node.attribute(BuiltinNodes.ID) == null) {
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
        if (BtTrees.visibleTrees(node.eResource()).containsKey(node.getTag())) {
            // BehaviorTree.CPP 3.8's loader only knows registered nodes by their tag, not trees.
            String subtree = "<SubTree ID=\"" + node.getTag() + "\"/>";
            warning("<" + node.getTag() + "/> names a BehaviorTree, which BehaviorTree.CPP 3.8 does not recognise "
                    + "by its tag (\"Node not recognized\"): write " + subtree, node, BT.getTreeNode_Tag(),
                    COMPACT_SUBTREE, subtree);
            return;
        }
        if (model.getNodesmodel() == null) {
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

    private static Attribute attribute(List<Attribute> attributes, String name) {
        return BtAttributes.find(attributes, name);
    }
}
