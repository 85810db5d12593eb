package org.miron.executor;

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
import org.miron.bt.bt.AlwaysFailure;
import org.miron.bt.bt.AlwaysSuccess;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BlackboardCheckDouble;
import org.miron.bt.bt.BlackboardCheckInt;
import org.miron.bt.bt.BlackboardCheckString;
import org.miron.bt.bt.Condition;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.CustomControl;
import org.miron.bt.bt.CustomDecorator;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.Delay;
import org.miron.bt.bt.Fallback;
import org.miron.bt.bt.FallbackStar;
import org.miron.bt.bt.ForceFailure;
import org.miron.bt.bt.ForceSuccess;
import org.miron.bt.bt.IfThenElse;
import org.miron.bt.bt.Inverter;
import org.miron.bt.bt.KeepRunningUntilFailure;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Repeat;
import org.miron.bt.bt.RetryUntilSuccess;
import org.miron.bt.bt.Sequence;
import org.miron.bt.bt.SequenceStar;
import org.miron.bt.bt.SetBlackboard;
import org.miron.bt.bt.Subtree;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.SubtreePlus;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.Timeout;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.bt.WhileDoElse;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;
import org.miron.executor.actions.*;
import org.miron.executor.controls.*;
import org.miron.executor.decorators.*;

/**
 * Turns a BT model (EMF, from the BT language) into a runnable {@link Tree}: one runtime node per
 * model node, subtrees expanded with their own blackboards, actions resolved by the registry.
 * Structural problems (missing or bad literal parameters, wrong child counts, unknown trees or
 * actions, recursive subtrees) are reported here, before anything runs.
 */
public final class TreeBuilder {
    private static final String SHARED = "__shared_blackboard";
    private static final String AUTOREMAP = "__autoremap";

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
        if (v4 == null) {
            return buildNode(node, info, blackboard, stack);
        }
        boolean isSubtree = node instanceof SubtreeNode
                || (node instanceof Action && !"Action".equals(node.getTag()) && trees(node).containsKey(node.getTag()));
        if (!isSubtree) {
            V4Nodes.declarePorts(info); // a SubTree's attributes remap, they declare nothing (as BT.CPP 4)
        }
        Node built;
        if (V4Nodes.isV4Builtin(node.getTag()) && !(node instanceof SubtreeNode)) {
            List<Node> children = new ArrayList<>();
            for (TreeNode child : V4Nodes.children(node)) {
                children.add(buildNode(child, blackboard, path, stack));
            }
            built = v4.create(node.getTag(), info, children);
        } else if (node instanceof SubtreeNode subtree) {
            built = subtreeV4(target(subtree, info), info, blackboard, stack);
        } else {
            built = buildNode(node, info, blackboard, stack);
        }
        built.useConditions(v4.conditions(node, path));
        return built;
    }

    /** Version-4 SubTree: its blackboard prepared by {@link V4Nodes#subtreeBlackboard}. */
    private Node subtreeV4(BehaviorTree tree, NodeInfo info, Blackboard parent, Deque<String> stack) {
        Blackboard blackboard = V4Nodes.subtreeBlackboard(info, parent);
        return new SubTreeNode(info, tree.getName(), blackboard, buildTree(tree, blackboard, info.path(), stack));
    }

    private Node buildNode(TreeNode node, NodeInfo info, Blackboard blackboard, Deque<String> stack) {
        String path = info.path();
        if (node instanceof ControlNode control) {
            return control(control, info, childrenOf(control, blackboard, path, stack));
        }
        if (node instanceof DecoratorNode decorator) {
            if (!decorator.getSurplus().isEmpty()) {
                throw new BtBuildException(path + ": a decorator has exactly one child, " + node.getTag() + " has "
                        + (1 + decorator.getSurplus().size()));
            }
            if (decorator.getNode() == null) {
                throw new BtBuildException(path + ": " + node.getTag() + " has no child");
            }
            return decorator(decorator, info, buildNode(decorator.getNode(), blackboard, path, stack));
        }
        if (node instanceof Subtree subtree) {
            return subtree(subtree, info, blackboard, stack);
        }
        if (node instanceof SubtreePlus subtreePlus) {
            return subtreePlus(subtreePlus, info, blackboard, stack);
        }
        if (node instanceof AlwaysSuccess) {
            return new AlwaysSuccessNode(info);
        }
        if (node instanceof AlwaysFailure) {
            return new AlwaysFailureNode(info);
        }
        if (node instanceof SetBlackboard) {
            return new SetBlackboardNode(info);
        }
        if (node instanceof Condition) {
            return registry.create(declaredOutputs.spec(node, requireId(node, info), ActionSpec.Kind.CONDITION, info));
        }
        if (node instanceof Action) {
            if (!"Action".equals(node.getTag())) {
                // compact form <X .../>: a tree ID used as a tag is a SubTree, anything else an action ID
                BehaviorTree tree = trees(node).get(node.getTag());
                if (tree != null) {
                    return v4 != null ? subtreeV4(tree, info, blackboard, stack) : plainSubtree(tree, info, blackboard, stack);
                }
                return registry.create(declaredOutputs.spec(node, node.getTag(), ActionSpec.Kind.ACTION, info));
            }
            return registry.create(declaredOutputs.spec(node, requireId(node, info), ActionSpec.Kind.ACTION, info));
        }
        throw new BtBuildException(path + ": unsupported node " + node.getTag());
    }

    private List<Node> childrenOf(ControlNode control, Blackboard blackboard, String path, Deque<String> stack) {
        List<Node> children = new ArrayList<>();
        for (TreeNode child : control.getNodes()) {
            children.add(buildNode(child, blackboard, path, stack));
        }
        return children;
    }

    private Node control(ControlNode control, NodeInfo info, List<Node> children) {
        String tag = control.getTag();
        if (control instanceof Sequence) {
            return "ReactiveSequence".equals(tag) ? ReactiveNode.sequence(info, children) : OrderedNode.sequence(info, children);
        }
        if (control instanceof Fallback) {
            return "ReactiveFallback".equals(tag) ? ReactiveNode.fallback(info, children) : OrderedNode.fallback(info, children);
        }
        if (control instanceof SequenceStar) {
            return OrderedNode.sequenceStar(info, children);
        }
        if (control instanceof FallbackStar) {
            return OrderedNode.fallbackStar(info, children);
        }
        if (control instanceof Parallel) {
            checkThreshold(info, ParallelNode.SUCCESS_THRESHOLD, true, children.size());
            checkThreshold(info, ParallelNode.FAILURE_THRESHOLD, false, children.size());
            return new ParallelNode(info, children);
        }
        if (control instanceof IfThenElse) {
            return new IfThenElseNode(info, children);
        }
        if (control instanceof WhileDoElse) {
            return new WhileDoElseNode(info, children);
        }
        if (control instanceof CustomControl custom) {
            return customControl(custom, info, children);
        }
        if (control instanceof Switch) {
            int cases;
            try {
                cases = Integer.parseInt(tag.substring("Switch".length()));
            } catch (RuntimeException e) {
                throw new BtBuildException(info.path() + ": unknown switch " + tag);
            }
            return new SwitchNode(info, cases, children, v4 == null ? null : registry.scriptingEnums());
        }
        throw new BtBuildException(info.path() + ": unsupported control node " + tag);
    }

    private Node decorator(DecoratorNode decorator, NodeInfo info, Node child) {
        if (decorator instanceof Inverter) {
            return new InverterNode(info, child);
        }
        if (decorator instanceof ForceSuccess) {
            return new ForceNode(info, child, NodeStatus.SUCCESS);
        }
        if (decorator instanceof ForceFailure) {
            return new ForceNode(info, child, NodeStatus.FAILURE);
        }
        if (decorator instanceof Repeat) {
            checkIntPort(info, LoopNode.NUM_CYCLES);
            return LoopNode.repeat(info, child);
        }
        if (decorator instanceof RetryUntilSuccess) {
            // both spellings, RetryUntilSuccesful (BT.CPP 3.5-3.6) and RetryUntilSuccessful
            checkIntPort(info, LoopNode.NUM_ATTEMPTS);
            return LoopNode.retry(info, child);
        }
        if (decorator instanceof Timeout) {
            checkIntPort(info, TimeoutNode.MSEC);
            return new TimeoutNode(info, child);
        }
        if (decorator instanceof KeepRunningUntilFailure) {
            return new KeepRunningUntilFailureNode(info, child);
        }
        if (decorator instanceof Delay) {
            checkIntPort(info, DelayNode.DELAY_MSEC);
            return new DelayNode(info, child);
        }
        if (decorator instanceof CustomDecorator custom) {
            return registry.createDecorator(requireCustomId(custom, info), info, child);
        }
        if (decorator instanceof BlackboardCheckInt) {
            return new BlackboardCheckNode(info, BlackboardCheckNode.Kind.INT, child);
        }
        if (decorator instanceof BlackboardCheckDouble) {
            return new BlackboardCheckNode(info, BlackboardCheckNode.Kind.DOUBLE, child);
        }
        if (decorator instanceof BlackboardCheckString) {
            return new BlackboardCheckNode(info, BlackboardCheckNode.Kind.STRING, child);
        }
        throw new BtBuildException(info.path() + ": unsupported decorator " + decorator.getTag());
    }

    /**
     * {@code <Control ID="x">} or a compact element with children {@code <x>...</x>}. The compact form
     * is also how a decorator can be written, so an ID registered as a decorator makes one, given the
     * element has exactly one child.
     */
    private Node customControl(CustomControl custom, NodeInfo info, List<Node> children) {
        String id = requireCustomId(custom, info);
        if ("Control".equals(custom.getTag()) || registry.isControlRegistered(id)) {
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

    private static String requireCustomId(TreeNode custom, NodeInfo info) {
        String id = BtTrees.customNodeId(custom);
        if (id == null || id.isBlank()) {
            throw new BtBuildException(info.path() + ": " + custom.getTag() + " needs an ID attribute");
        }
        return id;
    }

    /** SubTree: isolated blackboard unless __shared_blackboard; other attributes remap a key to a parent key by name. */
    private Node subtree(Subtree node, NodeInfo info, Blackboard parent, Deque<String> stack) {
        return plainSubtree(target(node, info), info, parent, stack);
    }

    /** Also a tree ID written as a tag (a SubTree); a value in braces is taken as the key it names. */
    private Node plainSubtree(BehaviorTree tree, NodeInfo info, Blackboard parent, Deque<String> stack) {
        boolean shared = booleanAttribute(info, SHARED);
        Blackboard blackboard = shared ? parent : parent.createChild();
        if (!shared) {
            remapByName(info, blackboard);
        }
        return new SubTreeNode(info, tree.getName(), blackboard, buildTree(tree, blackboard, info.path(), stack));
    }

    private static void remapByName(NodeInfo info, Blackboard blackboard) {
        info.ports().attributes().forEach((port, value) -> {
            if (!port.equals("name") && !port.equals(SHARED)) {
                blackboard.remap(port, Ports.blackboardKey(port, value).orElse(value), info.ports().madeBy(port));
            }
        });
    }

    /**
     * SubTreePlus: always its own blackboard; {@code port="{parentKey}"} remaps, a literal is written
     * into the subtree's blackboard, {@code __autoremap="true"} remaps every other key the subtree's
     * nodes use to the parent key of the same name (BT.CPP 3 ignores __shared_blackboard here).
     */
    private Node subtreePlus(SubtreePlus node, NodeInfo info, Blackboard parent, Deque<String> stack) {
        BehaviorTree tree = target(node, info);
        Blackboard blackboard = parent.createChild();
        Set<String> mapped = info.ports().bindInto(blackboard,
                port -> port.equals("name") || port.equals(SHARED) || port.equals(AUTOREMAP));
        if (booleanAttribute(info, AUTOREMAP)) {
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
        String id = node.attribute("ID");
        if (id == null || id.isBlank()) {
            throw new BtBuildException(info.path() + ": " + node.getTag() + " needs an ID attribute");
        }
        return id;
    }

    /** A required integer parameter: present, and an integer when written as a literal. */
    private static void checkIntPort(NodeInfo info, String port) {
        String value = info.ports().raw(port);
        if (value == null) {
            throw new BtBuildException(info.path() + ": missing parameter " + port);
        }
        if (Ports.blackboardKey(port, value).isEmpty()) {
            try {
                Conversions.toInt(value);
            } catch (IllegalArgumentException e) {
                throw new BtBuildException(info.path() + ": " + port + ": " + e.getMessage());
            }
        }
    }

    private static void checkThreshold(NodeInfo info, String port, boolean required, int children) {
        String value = info.ports().raw(port);
        if (value == null) {
            if (required) {
                throw new BtBuildException(info.path() + ": missing parameter " + port);
            }
            return;
        }
        checkIntPort(info, port);
        if (Ports.blackboardKey(port, value).isEmpty()) {
            try {
                ParallelNode.resolveThreshold(port, Conversions.toInt(value), children);
            } catch (BtRuntimeException e) {
                throw new BtBuildException(info.path() + ": " + e.getMessage());
            }
        }
    }

    private static Map<String, String> attributes(TreeNode node) {
        Map<String, String> attributes = new LinkedHashMap<>();
        for (Attribute attribute : node.getAttributes()) {
            attributes.putIfAbsent(attribute.getName(), attribute.getValue() == null ? "" : attribute.getValue());
        }
        return attributes;
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
