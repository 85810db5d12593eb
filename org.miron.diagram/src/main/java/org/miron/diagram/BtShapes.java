package org.miron.diagram;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtTrees;

/**
 * The shapes of a BT file: every tree as a frame, each node with its kind (from the built-in
 * catalogue, else the file's {@code <TreeNodesModel>}), its name and its port values, and every
 * SubTree call linked to the frame of the tree it calls ({@link #of}). {@link #expanded} draws one
 * tree as it runs instead, each called tree inline below its call, numbered as the executor numbers
 * the nodes it publishes (docs/wire-formats.md, {@code miron.bt.status}).
 */
public final class BtShapes {
    /** Longer port values are cut with an ellipsis. */
    static final int MAX_VALUE = 28;

    private final Map<String, NodeDeclaration> declared;
    private final Map<String, BehaviorTree> visible;
    private final ShapeKinds kinds;
    private final boolean woven;
    /** Model elements to their shapes, for the MIRoN overlay (definitions view only). */
    private final Map<EObject, Shape> index = new java.util.HashMap<>();
    /** The ids of the SubTree calls drawn expanded (definitions view only). */
    private Set<String> expandedCalls = Set.of();

    private BtShapes(Resource resource) {
        this.declared = NodeDeclarations.visibleFrom(resource);
        this.visible = BtTrees.visibleTrees(resource);
        this.kinds = new ShapeKinds(declared);
        this.woven = resource.getURI().lastSegment() != null && resource.getURI().lastSegment().endsWith(".ext.xml");
    }

    /** Every tree of the file, calls linked to the trees they call (those of included files too). */
    public static Diagram of(Resource resource) {
        return of(resource, Set.of());
    }

    /**
     * {@link #of}, with the called tree drawn below each SubTree call whose node id is in
     * {@code expanded} (an editor's expand/collapse); the called tree keeps its own frame.
     */
    public static Diagram of(Resource resource, Set<String> expanded) {
        return definitions(resource, expanded).diagram;
    }

    /** {@link #of} with each tree node's shape, for the layers drawn over it. */
    static Indexed definitions(Resource resource) {
        return definitions(resource, Set.of());
    }

    private static Indexed definitions(Resource resource, Set<String> expanded) {
        BtShapes shapes = new BtShapes(resource);
        shapes.expandedCalls = expanded;
        Diagram diagram = new Diagram(resource.getURI().lastSegment());
        for (BehaviorTree tree : BtTrees.treesOf(resource)) {
            String name = BtTrees.runName(tree);
            Frame frame = new Frame(frameId(name), name);
            List<TreeNode> nodes = tree.getNodes();
            for (int i = 0; i < nodes.size(); i++) {
                frame.roots().add(shapes.definition(nodes.get(i), name + ":" + i, diagram, frame));
            }
            diagram.frames().add(frame);
        }
        return new Indexed(diagram, shapes.index);
    }

    /** A diagram with each tree node's shape. */
    record Indexed(Diagram diagram, Map<EObject, Shape> shapes) {
    }

    /**
     * One tree as the executor builds it: every SubTree call with the called tree's root as its only
     * child. Node ids are index paths from the root ("0", "0.1", "0.1.0"). {@code treeId} null: the
     * tree main_tree_to_execute names, else the first.
     */
    public static Diagram expanded(Resource resource, String treeId) {
        BtShapes shapes = new BtShapes(resource);
        BehaviorTree tree = mainTree(resource, treeId);
        Diagram diagram = new Diagram(resource.getURI().lastSegment());
        if (tree == null) {
            return diagram;
        }
        Frame frame = new Frame(frameId(BtTrees.runName(tree)), BtTrees.runName(tree));
        if (!tree.getNodes().isEmpty()) {
            Deque<String> stack = new ArrayDeque<>();
            stack.push(BtTrees.runName(tree));
            frame.roots().add(shapes.inline(tree.getNodes().get(0), "0", stack));
        }
        diagram.frames().add(frame);
        return diagram;
    }

    /** The tree to draw: by ID, else main_tree_to_execute, else the file's first; null when none. */
    public static BehaviorTree mainTree(Resource resource, String treeId) {
        Map<String, BehaviorTree> visible = BtTrees.visibleTrees(resource);
        if (treeId != null) {
            return visible.get(treeId);
        }
        if (!resource.getContents().isEmpty() && resource.getContents().get(0) instanceof BTModel model) {
            String main = BtAttributes.value(model.getAttributes(), "main_tree_to_execute");
            if (main != null && visible.containsKey(main)) {
                return visible.get(main);
            }
        }
        List<BehaviorTree> trees = BtTrees.treesOf(resource);
        return trees.isEmpty() ? null : trees.get(0);
    }

    public static String frameId(String treeName) {
        return "tree:" + treeName;
    }

    private Shape definition(TreeNode node, String id, Diagram diagram, Frame frame) {
        Shape shape = shape(node, id);
        index.put(node, shape);
        BehaviorTree called = calledTree(node);
        if (called != null) {
            String target = frameId(BtTrees.runName(called));
            shape.link(target);
            diagram.links().add(new Diagram.Link(frame.id(), target, "edge:call"));
            boolean open = expandedCalls.contains(id) && !called.getNodes().isEmpty();
            shape.expanded(open);
            if (open) {
                Deque<String> stack = new ArrayDeque<>();
                stack.push(frame.title());
                stack.push(BtTrees.runName(called));
                shape.children().add(inline(called.getNodes().get(0), id + ".0", stack));
                return shape;
            }
        }
        List<TreeNode> children = BtTrees.children(node);
        for (int i = 0; i < children.size(); i++) {
            shape.children().add(definition(children.get(i), id + "." + i, diagram, frame));
        }
        return shape;
    }

    private Shape inline(TreeNode node, String id, Deque<String> stack) {
        Shape shape = shape(node, id);
        BehaviorTree called = calledTree(node);
        if (called != null) {
            String name = BtTrees.runName(called);
            if (stack.contains(name) || called.getNodes().isEmpty()) {
                shape.cssClasses().add("recursive"); // the executor refuses it; drawn once, not forever
            } else {
                stack.push(name);
                shape.children().add(inline(called.getNodes().get(0), id + ".0", stack));
                stack.pop();
            }
            return shape;
        }
        List<TreeNode> children = BtTrees.children(node);
        for (int i = 0; i < children.size(); i++) {
            shape.children().add(inline(children.get(i), id + "." + i, stack));
        }
        return shape;
    }

    private BehaviorTree calledTree(TreeNode node) {
        if (node instanceof SubtreeNode call) {
            BehaviorTree tree = call.getBehaviorTree();
            return tree == null || tree.eIsProxy() ? null : tree;
        }
        return BtTrees.isCompactSubtree(node) ? visible.get(node.getTag()) : null;
    }

    private Shape shape(TreeNode node, String id) {
        ShapeKind kind = kinds.of(node, calledTree(node) != null);
        String typeName = kinds.typeName(node, calledTree(node));
        String name = BtAttributes.value(node.getAttributes(), "name");
        String title = name != null && !name.isBlank() ? name : typeName;
        String type = title.equals(typeName) ? kind.word() : typeName;
        Shape shape = new Shape(id, kind, title, type).span(SourceSpan.of(node));
        for (Attribute attribute : node.getAttributes()) {
            if (!"name".equals(attribute.getName()) && !("ID".equals(attribute.getName()) && kinds.idIsType(node))) {
                shape.ports().add(new Shape.Port(attribute.getName(), shorten(attribute.getValue()), null));
            }
        }
        if (woven && kinds.isWoven(node)) {
            shape.cssClasses().add("woven");
        }
        return shape;
    }

    static String shorten(String value) {
        String text = value == null ? "" : value.replaceAll("\\s+", " ");
        return text.length() <= MAX_VALUE ? text : text.substring(0, MAX_VALUE - 1) + "…";
    }
}
