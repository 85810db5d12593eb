package org.miron.bt.util;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.EcoreUtil2;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.LeafNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.bt.TreeNodesModel;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.scoping.BtGlobalScopeProvider;

/** Navigation over a BT file and the files it includes. */
public final class BtTrees {
    private static final Pattern DECLARED_ID = Pattern.compile("\\bID\\s*=\\s*[\"']([^\"']+)[\"']");
    /** A declaration with its kind: {@code <Decorator ID="RateController">}. */
    private static final Pattern DECLARATION = Pattern.compile(
            "<\\s*([A-Za-z_][\\w.:-]*)[^<>]*?\\bID\\s*=\\s*[\"']([^\"']+)[\"']");

    private BtTrees() {
    }

    public static List<BehaviorTree> treesOf(Resource resource) {
        if (resource == null || resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            return List.of();
        }
        return ((BTModel) resource.getContents().get(0)).getTrees();
    }

    /** The files a resource includes, transitively, loaded into its resource set. */
    public static List<Resource> includedResources(Resource resource) {
        List<Resource> result = new ArrayList<>();
        Set<URI> seen = new LinkedHashSet<>();
        seen.add(resource.getURI());
        Deque<Resource> pending = new ArrayDeque<>();
        pending.add(resource);
        while (!pending.isEmpty()) {
            for (URI uri : BtGlobalScopeProvider.includesOf(pending.poll())) {
                if (seen.add(uri)) {
                    Resource included = EcoreUtil2.getResource(resource, uri.toString());
                    if (included != null) {
                        result.add(included);
                        pending.add(included);
                    }
                }
            }
        }
        return result;
    }

    /** Trees by ID visible from a file: its own first, then its includes' (first wins, as in BT.CPP). */
    public static Map<String, BehaviorTree> visibleTrees(Resource resource) {
        Map<String, BehaviorTree> trees = new LinkedHashMap<>();
        for (BehaviorTree tree : treesOf(resource)) {
            if (tree.getName() != null) {
                trees.putIfAbsent(tree.getName(), tree);
            }
        }
        for (Resource included : includedResources(resource)) {
            for (BehaviorTree tree : treesOf(included)) {
                if (tree.getName() != null) {
                    trees.putIfAbsent(tree.getName(), tree);
                }
            }
        }
        return trees;
    }

    /** The trees of a BT resource, or null when the resource is missing or not a BT file. */
    public static List<BehaviorTree> treesOrNull(Resource resource) {
        return resource == null || resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof BTModel)
                ? null : treesOf(resource);
    }

    /** How messages name a tree: by its ID, or as "the BehaviorTree without ID". */
    public static String displayName(BehaviorTree tree) {
        return tree.getName() == null || tree.getName().isEmpty() ? "the BehaviorTree without ID"
                : "BehaviorTree '" + tree.getName() + "'";
    }

    /**
     * The name a tree runs under: its ID, else (a file's tree without ID) "BehaviorTree_k", k
     * counting the file's trees without ID from 0, the form BehaviorTree.CPP 3 gives them.
     */
    public static String runName(BehaviorTree tree) {
        if (tree.getName() != null && !tree.getName().isEmpty()) {
            return tree.getName();
        }
        int k = 0;
        if (tree.eContainer() instanceof BTModel model) {
            for (BehaviorTree other : model.getTrees()) {
                if (other == tree) {
                    break;
                }
                if (other.getName() == null || other.getName().isEmpty()) {
                    k++;
                }
            }
        }
        return "BehaviorTree_" + k;
    }

    /** Same content modulo whitespace and comments: the same elements, attributes and references. */
    public static boolean sameContent(BehaviorTree a, BehaviorTree b) {
        return EcoreUtil.equals(a, b);
    }

    /** Node IDs declared in a TreeNodesModel (its content is opaque, so this reads it leniently). */
    public static Set<String> declaredNodeIds(TreeNodesModel nodesModel) {
        Set<String> ids = new LinkedHashSet<>();
        if (nodesModel != null && nodesModel.getContent() != null) {
            Matcher matcher = DECLARED_ID.matcher(nodesModel.getContent());
            while (matcher.find()) {
                ids.add(matcher.group(1));
            }
        }
        return ids;
    }

    /**
     * Node IDs declared in a TreeNodesModel with the element that declares them (Action, Condition,
     * Decorator, Control, SubTree), read as leniently as {@link #declaredNodeIds}.
     */
    public static Map<String, String> declaredNodeKinds(TreeNodesModel nodesModel) {
        Map<String, String> kinds = new LinkedHashMap<>();
        if (nodesModel != null && nodesModel.getContent() != null) {
            Matcher matcher = DECLARATION.matcher(nodesModel.getContent());
            while (matcher.find()) {
                kinds.putIfAbsent(matcher.group(2), matcher.group(1));
            }
        }
        return kinds;
    }

    /** The ID a custom control or decorator is registered under: its ID attribute in the explicit form, else its tag. */
    public static String customNodeId(TreeNode node) {
        boolean explicit = "Control".equals(node.getTag()) || "Decorator".equals(node.getTag());
        return explicit ? node.attribute("ID") : node.getTag();
    }

    /** {@code <Tree/>}: a compact element whose tag is a tree visible from the file (BT.CPP 3 only). */
    public static boolean isCompactSubtree(TreeNode node) {
        return node instanceof org.miron.bt.bt.Action && node.getTag() != null && !"Action".equals(node.getTag())
                && visibleTreesOf(node).containsKey(node.getTag());
    }

    /** Trees visible from an element: of its file and includes, or of its model when it is in no file. */
    public static Map<String, BehaviorTree> visibleTreesOf(org.eclipse.emf.ecore.EObject element) {
        if (element.eResource() != null) {
            return visibleTrees(element.eResource());
        }
        Map<String, BehaviorTree> trees = new LinkedHashMap<>();
        BTModel model = EcoreUtil2.getContainerOfType(element, BTModel.class);
        if (model != null) {
            model.getTrees().forEach(tree -> trees.putIfAbsent(tree.getName(), tree));
        }
        return trees;
    }

    /**
     * {@code <Action ID="x">}, {@code <Condition ID="x">}, {@code <Control ID="x">}, {@code <Decorator ID="x">}:
     * the catalogue's explicit forms that name a registered node (not a tree).
     */
    public static boolean isExplicitForm(TreeNode node) {
        return NodeCatalogue.find(node.getTag()).filter(n -> n.explicitForm() && n.kind() != NodeKind.SUBTREE)
                .isPresent();
    }

    /** The child elements of a node, whatever metamodel class the grammar gave it (a decorator's surplus too). */
    public static List<TreeNode> children(TreeNode node) {
        if (node instanceof ControlNode control) {
            return control.getNodes();
        }
        List<TreeNode> children = new ArrayList<>();
        if (node instanceof DecoratorNode decorator) {
            if (decorator.getNode() != null) {
                children.add(decorator.getNode());
            }
            children.addAll(decorator.getSurplus());
        } else if (node instanceof LeafNode leaf) {
            children.addAll(leaf.getSurplus());
        }
        return children;
    }
}
