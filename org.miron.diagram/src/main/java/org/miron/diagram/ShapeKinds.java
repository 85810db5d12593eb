package org.miron.diagram;

import java.util.Map;
import java.util.Optional;

import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.util.BtAttributes;

/**
 * The kind and type name of a tree node: built-ins from the catalogue (org.miron.bt.nodes), the
 * application's nodes from the {@code <TreeNodesModel>} the file sees, else from the element's form
 * (children make a control, one child a decorator, none an action).
 */
final class ShapeKinds {
    private final Map<String, NodeDeclaration> declared;

    ShapeKinds(Map<String, NodeDeclaration> declared) {
        this.declared = declared;
    }

    ShapeKind of(TreeNode node, boolean calls) {
        Optional<NodeModel> builtin = NodeCatalogue.find(node.getTag());
        if (calls || builtin.map(b -> b.kind() == NodeKind.SUBTREE).orElse(false)) {
            return ShapeKind.SUBTREE;
        }
        if (builtin.isPresent()) {
            NodeModel model = builtin.get();
            if (model.explicitForm()) {
                return fromKind(model.kind());
            }
            return switch (model.kind()) {
                case CONTROL -> ShapeKind.CONTROL;
                case DECORATOR -> ShapeKind.DECORATOR;
                default -> ShapeKind.BUILTIN;
            };
        }
        NodeDeclaration declaration = declared.get(node.getTag());
        if (declaration != null) {
            for (NodeKind kind : NodeKind.values()) {
                if (kind.xmlName().equals(declaration.kind())) {
                    return fromKind(kind);
                }
            }
        }
        return node instanceof ControlNode ? ShapeKind.CONTROL
                : node instanceof DecoratorNode ? ShapeKind.DECORATOR : ShapeKind.ACTION;
    }

    private static ShapeKind fromKind(NodeKind kind) {
        return switch (kind) {
            case ACTION -> ShapeKind.ACTION;
            case CONDITION -> ShapeKind.CONDITION;
            case CONTROL -> ShapeKind.CONTROL;
            case DECORATOR -> ShapeKind.DECORATOR;
            case SUBTREE -> ShapeKind.SUBTREE;
        };
    }

    /** Whether the ID attribute names the node's type (explicit forms, SubTree calls) rather than being a port. */
    boolean idIsType(TreeNode node) {
        return NodeCatalogue.find(node.getTag()).map(NodeModel::explicitForm).orElse(false);
    }

    /** The node's type as written: the ID of an explicit form or call, the called tree, else the tag. */
    String typeName(TreeNode node, BehaviorTree called) {
        if (idIsType(node)) {
            String id = BtAttributes.value(node.getAttributes(), "ID");
            if (id != null && !id.isBlank()) {
                return id;
            }
            if (called != null && called.getName() != null) {
                return called.getName();
            }
        }
        return node.getTag() == null ? "?" : node.getTag();
    }

    /**
     * A node the weaver adds (docs/generators.md): a VariantAction, the monitoring Parallel and Repeat
     * ({@code monitoring_...}), or a variant Switch (its variable a varpoint's {@code {<vp>_sel}} key).
     */
    boolean isWoven(TreeNode node) {
        String name = BtAttributes.value(node.getAttributes(), "name");
        String variable = BtAttributes.value(node.getAttributes(), "variable");
        return "VariantAction".equals(typeName(node, null)) || name != null && name.startsWith("monitoring_")
                || node.getTag() != null && node.getTag().startsWith("Switch") && variable != null
                        && variable.matches("\\{\\w+_sel}");
    }
}
