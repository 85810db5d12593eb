package org.miron.executor;

import static org.miron.bt.nodes.BuiltinNodes.ID;
import static org.miron.bt.nodes.BuiltinNodes.SHARED_BLACKBOARD;
import static org.miron.bt.nodes.BuiltinNodes.V3_AUTOREMAP;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.Condition;
import org.miron.bt.bt.CustomControl;
import org.miron.bt.bt.CustomDecorator;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;
import org.miron.executor.decorators.SubTreeNode;

/**
 * Turns a BT model (EMF, from the BT language) into a runnable {@link Tree}: one runtime node per
 * model node, subtrees expanded with their own blackboards, actions resolved by the registry,
 * built-ins made by their version's table ({@link BuiltinFactories}) after the catalogue's checks.
 * Structural problems (missing or bad literal parameters, wrong child counts, unknown trees or
 * actions, recursive subtrees) are reported here, before anything runs.
 */
public final class TreeBuilder {
    private final ActionRegistry registry;
    private final TreeContext context;
    private final Map<Resource, Map<String, BehaviorTree>> visibleTrees = new HashMap<>();
    private final DeclaredOutputs declaredOutputs = new DeclaredOutputs();
    /** Makes the version-4 nodes while a version-4 tree is built; null for version 3. */
    private V4Nodes v4;

    public TreeBuilder(ActionRegistry registry, TreeContext context) {
        this.registry = registry;
        this.context = context;
    }

    /** Loads a .bt or .ext.xml file through the BT language and builds its main tree. */
    public Tree build(Path file) {
        return build(new BtLoader().load(file).model());
    }

    /** The tree main_tree_to_execute names, or the only tree of the file. */
    public Tree build(BTModel model) {
        String main = BtAttributes.value(model.getAttributes(), "main_tree_to_execute");
        if (main != null) {
            return build(model, main);
        }
        if (model.getTrees().size() == 1) {
            return build(model.getTrees().get(0));
        }
        throw new BtBuildException("the file holds " + model.getTrees().size()
                + " trees and no main_tree_to_execute saying which one to run");
    }

    /** The tree with this ID, in the file or in a file it includes. */
    public Tree build(BTModel model, String treeId) {
        BehaviorTree tree = trees(model).get(treeId);
        if (tree == null) {
            throw new BtBuildException("no tree with ID '" + treeId + "' (known: " + trees(model).keySet() + ")");
        }
        return build(tree);
    }

    /** The tree, with the semantics of its file's version (BTCPP_format, absent = 3). */
    public Tree build(BehaviorTree tree) {
        Blackboard blackboard = Blackboard.create();
        v4 = BtFormats.versionOf(tree) == 4 ? new V4Nodes(registry.scriptingEnums()) : null;
        try {
            Node root = buildTree(tree, blackboard, "", new ArrayDeque<>());
            return new Tree(BtTrees.runName(tree), root, blackboard, context, v4 != null ? 4 : 3);
        } finally {
            v4 = null;
        }
    }

    private Map<String, BehaviorTree> trees(EObject object) {
        Resource resource = object.eResource();
        if (resource == null) {
            Map<String, BehaviorTree> local = new LinkedHashMap<>();
            EObject top = org.eclipse.emf.ecore.util.EcoreUtil.getRootContainer(object);
            if (top instanceof BTModel model) {
                model.getTrees().forEach(t -> local.putIfAbsent(t.getName(), t));
            }
            return local;
        }
        return visibleTrees.computeIfAbsent(resource, BtTrees::visibleTrees);
    }

    private Node buildTree(BehaviorTree tree, Blackboard blackboard, String parentPath, Deque<String> stack) {
        // A file's tree without ID runs under the name BehaviorTree.CPP 3 gives it (BehaviorTree_0).
        String name = BtTrees.runName(tree);
        String where = parentPath.isEmpty() ? name : parentPath;
        if (stack.contains(name)) {
            throw new BtBuildException(where + ": tree '" + name + "' includes itself through " + String.join(" -> ", stack));
        }
        if (tree.getNodes().size() != 1) {
            throw new BtBuildException(where + ": tree '" + name + "' must have exactly one root node, has " + tree.getNodes().size());
        }
        stack.addLast(name);
        Node root = buildNode(tree.getNodes().get(0), blackboard, parentPath.isEmpty() ? name : parentPath, stack);
        stack.removeLast();
        return root;
    }

    private Node buildNode(TreeNode node, Blackboard blackboard, String parentPath, Deque<String> stack) {
        String name = displayName(node);
        String path = parentPath + "/" + name;
        NodeInfo info = new NodeInfo(name, path, new Ports(path, attributes(node), blackboard), context);
        if (v4 != null && !isSubtree(node)) {
            V4Nodes.declarePorts(info); // a SubTree's attributes remap, they declare nothing (as BT.CPP 4)
        }
        Node built = make(node, info, blackboard, stack);
        built.useElement(registrationName(node, built), kindOf(node, built));
        if (v4 != null) {
            built.useConditions(v4.conditions(node, path));
        }
        return built;
    }

    private int version() {
        return v4 != null ? NodeCatalogue.V4 : NodeCatalogue.V3;
    }

    private boolean isSubtree(TreeNode node) {
        return node instanceof SubtreeNode || BtTrees.isCompactSubtree(node);
    }

    /**
     * A built-in by its version's factory table; SubTree and SubTreePlus, and the explicit forms
     * naming a registered node, here; any other element is a node the application registered
     * under its tag, or a tree named by its tag (BT.CPP 3's compact SubTree).
     */
    private Node make(TreeNode node, NodeInfo info, Blackboard blackboard, Deque<String> stack) {
        String tag = node.getTag();
        NodeModel model = BuiltinFactories.builtin(tag, version())
                .or(() -> NodeCatalogue.find(tag).filter(NodeModel::explicitForm)).orElse(null);
        if (model != null && model.kind() == NodeKind.SUBTREE && node instanceof SubtreeNode subtree) {
            return subtree(subtree, model, info, blackboard, stack);
        }
        List<Node> children = new ArrayList<>();
        for (TreeNode child : BtTrees.children(node)) {
            children.add(buildNode(child, blackboard, info.path(), stack));
        }
        if (model == null) {
            return registered(node, info, blackboard, stack, children);
        }
        if (!model.explicitForm()) {
            Map<String, Integer> enums = v4 != null ? v4.enums() : Map.of();
            return BuiltinFactories.create(model, version(), info, children, enums);
        }
        BuiltinChecks.checkChildren(model, info, children.size());
        String id = requireId(node, info);
        switch (model.kind()) {
        case CONTROL:
            return registry.createControl(id, info, children);
        case DECORATOR:
            return registry.createDecorator(id, info, children.get(0));
        case CONDITION:
            return registry.create(declaredOutputs.spec(node, id, ActionSpec.Kind.CONDITION, info));
        default:
            return registry.create(declaredOutputs.spec(node, id, ActionSpec.Kind.ACTION, info));
        }
    }

    /**
     * An element no built-in of the version names, e.g. {@code <GoTo/>}: a tree of that ID (a
     * SubTree), else the node registered under the tag; with children, a registered control, or
     * a registered decorator when it has one child.
     */
    private Node registered(TreeNode node, NodeInfo info, Blackboard blackboard, Deque<String> stack,
            List<Node> children) {
        String tag = node.getTag();
        NodeKind kind = NodeCatalogue.find(tag).map(NodeModel::kind).orElse(null);
        if (children.isEmpty() && kind != NodeKind.CONTROL && kind != NodeKind.DECORATOR) {
            BehaviorTree tree = trees(node).get(tag);
            if (tree != null) {
                return v4 != null ? subtreeV4(tree, info, blackboard, stack) : plainSubtree(tree, info, blackboard, stack);
            }
            ActionSpec.Kind spec = kind == NodeKind.CONDITION ? ActionSpec.Kind.CONDITION : ActionSpec.Kind.ACTION;
            return registry.create(declaredOutputs.spec(node, tag, spec, info));
        }
        return customControl(tag, info, children);
    }

    /** Version-4 SubTree: its blackboard prepared by {@link V4Nodes#subtreeBlackboard}. */
    private Node subtreeV4(BehaviorTree tree, NodeInfo info, Blackboard parent, Deque<String> stack) {
        Blackboard blackboard = V4Nodes.subtreeBlackboard(info, parent);
        return new SubTreeNode(info, tree.getName(), blackboard, buildTree(tree, blackboard, info.path(), stack));
    }

    private Node subtree(SubtreeNode node, NodeModel model, NodeInfo info, Blackboard parent, Deque<String> stack) {
        BehaviorTree tree = target(node, info);
        if (v4 != null) {
            return subtreeV4(tree, info, parent, stack);
        }
        return "SubTreePlus".equals(model.tag()) ? subtreePlus(tree, info, parent, stack)
                : plainSubtree(tree, info, parent, stack);
    }

    /**
     * A compact element with children {@code <x>...</x>}: a registered control, or, as the compact
     * form is also how a decorator can be written, the decorator registered as x given one child.
     */
    private Node customControl(String id, NodeInfo info, List<Node> children) {
        if (registry.isControlRegistered(id)) {
            return registry.createControl(id, info, children);
        }
        if (!registry.isDecoratorRegistered(id)) {
            throw new BtBuildException(info.path() + ": no control node or decorator is registered for ID '" + id
                    + "' (register it with ActionRegistry.registerControl or registerDecorator)");
        }
        if (children.size() != 1) {
            throw new BtBuildException(info.path() + ": a decorator has exactly one child, " + id + " has "
                    + children.size());
        }
        return registry.createDecorator(id, info, children.get(0));
    }

    /** SubTree: isolated blackboard unless __shared_blackboard; other attributes remap a key to a parent key by name. */
    private Node plainSubtree(BehaviorTree tree, NodeInfo info, Blackboard parent, Deque<String> stack) {
        boolean shared = booleanAttribute(info, SHARED_BLACKBOARD);
        Blackboard blackboard = shared ? parent : parent.createChild();
        if (!shared) {
            remapByName(info, blackboard);
        }
        return new SubTreeNode(info, tree.getName(), blackboard, buildTree(tree, blackboard, info.path(), stack));
    }

    private static void remapByName(NodeInfo info, Blackboard blackboard) {
        info.ports().attributes().forEach((port, value) -> {
            if (!port.equals("name") && !port.equals(SHARED_BLACKBOARD)) {
                blackboard.remap(port, Ports.blackboardKey(port, value).orElse(value), info.ports().madeBy(port));
            }
        });
    }

    /**
     * SubTreePlus: always its own blackboard; {@code port="{parentKey}"} remaps, a literal is written
     * into the subtree's blackboard, {@code __autoremap="true"} remaps every other key the subtree's
     * nodes use to the parent key of the same name (BT.CPP 3 ignores __shared_blackboard here).
     */
    private Node subtreePlus(BehaviorTree tree, NodeInfo info, Blackboard parent, Deque<String> stack) {
        Blackboard blackboard = parent.createChild();
        Set<String> mapped = info.ports().bindInto(blackboard,
                port -> port.equals("name") || port.equals(SHARED_BLACKBOARD) || port.equals(V3_AUTOREMAP));
        if (booleanAttribute(info, V3_AUTOREMAP)) {
            for (String key : keysUsedIn(tree)) {
                if (!mapped.contains(key)) {
                    blackboard.remap(key, key);
                }
            }
        }
        return new SubTreeNode(info, tree.getName(), blackboard, buildTree(tree, blackboard, info.path(), stack));
    }

    /** The blackboard keys a tree's own nodes point at (as BT.CPP's getPortsRecursively). */
    private static Set<String> keysUsedIn(BehaviorTree tree) {
        Set<String> keys = new LinkedHashSet<>();
        for (TreeIterator<EObject> it = tree.eAllContents(); it.hasNext();) {
            if (it.next() instanceof Attribute attribute) {
                Ports.blackboardKey(attribute.getName(), attribute.getValue()).ifPresent(keys::add);
            }
        }
        return keys;
    }

    private static BehaviorTree target(SubtreeNode node, NodeInfo info) {
        BehaviorTree tree = node.getBehaviorTree();
        if (tree == null || tree.eIsProxy() || tree.getName() == null) {
            throw new BtBuildException(info.path() + ": " + node.getTag() + " refers to an unknown tree");
        }
        return tree;
    }

    private static boolean booleanAttribute(NodeInfo info, String name) {
        String value = info.ports().raw(name);
        if (value == null) {
            return false;
        }
        try {
            return Conversions.toBoolean(value);
        } catch (IllegalArgumentException e) {
            throw new BtBuildException(info.path() + ": " + name + ": " + e.getMessage());
        }
    }

    private static String requireId(TreeNode node, NodeInfo info) {
        String id = node.attribute(ID);
        if (id == null || id.isBlank()) {
            throw new BtBuildException(info.path() + ": " + node.getTag() + " needs an ID attribute");
        }
        return id;
    }

    private static Map<String, String> attributes(TreeNode node) {
        Map<String, String> attributes = new LinkedHashMap<>();
        for (Attribute attribute : node.getAttributes()) {
            attributes.putIfAbsent(attribute.getName(), attribute.getValue() == null ? "" : attribute.getValue());
        }
        return attributes;
    }

    /** As BehaviorTree.CPP's registrationName: SubTree, the ID of an explicit-form node, else the tag. */
    private static String registrationName(TreeNode node, Node built) {
        if (built instanceof SubTreeNode) {
            return "SubTree";
        }
        boolean explicit = NodeCatalogue.find(node.getTag()).map(NodeModel::explicitForm).orElse(false);
        String id = node.attribute(ID);
        return explicit && id != null && !id.isBlank() ? id : node.getTag();
    }

    private NodeKind kindOf(TreeNode node, Node built) {
        if (built instanceof SubTreeNode) {
            return NodeKind.SUBTREE;
        }
        if (built instanceof ControlNode) {
            return NodeKind.CONTROL;
        }
        if (built instanceof DecoratorNode) {
            return NodeKind.DECORATOR;
        }
        NodeModel model = BuiltinFactories.builtin(node.getTag(), version())
                .or(() -> NodeCatalogue.find(node.getTag())).orElse(null);
        return node instanceof Condition || model != null && model.kind() == NodeKind.CONDITION ? NodeKind.CONDITION
                : NodeKind.ACTION;
    }

    /** The name attribute, else what identifies the node: the action ID, the tree ID, the tag. */
    private static String displayName(TreeNode node) {
        String name = node.attribute("name");
        if (name != null && !name.isBlank()) {
            return name;
        }
        if (node instanceof SubtreeNode subtree && subtree.getBehaviorTree() != null && subtree.getBehaviorTree().getName() != null) {
            return subtree.getBehaviorTree().getName();
        }
        boolean registered = node instanceof Action || node instanceof Condition || node instanceof CustomControl
                || node instanceof CustomDecorator;
        if (registered && node.attribute("ID") != null) {
            return node.attribute("ID");
        }
        return node.getTag();
    }
}
