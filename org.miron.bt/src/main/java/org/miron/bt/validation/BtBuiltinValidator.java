package org.miron.bt.validation;

import static org.miron.bt.validation.BtIssueCodes.*;

import java.util.List;

import org.eclipse.emf.ecore.EPackage;
import org.eclipse.xtext.validation.AbstractDeclarativeValidator;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.EValidatorRegistrar;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.IfThenElse;
import org.miron.bt.bt.LeafNode;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.bt.WhileDoElse;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.nodes.Children;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.nodes.PortType;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;

/**
 * What the catalogue of built-ins (org.miron.bt.nodes) says of a node, checked: the ports its
 * version requires, literals its port types cannot convert, and how many children it takes. A
 * tag that is not a built-in of the file's version is a custom node (or the other version's,
 * reported by BtVersionValidator): its ports are the application's. Composed into BtValidator.
 */
public class BtBuiltinValidator extends AbstractDeclarativeValidator {

    private static final BtPackage BT = BtPackage.eINSTANCE;

    @Override
    public void register(EValidatorRegistrar registrar) {
        // Runs as part of BtValidator (@ComposedChecks), not on its own.
    }

    @Override
    protected List<EPackage> getEPackages() {
        return List.of(BT);
    }

    @Check
    public void checkPorts(TreeNode node) {
        int version = BtFormats.versionOf(node);
        NodeModel model = node.getTag() == null ? null : NodeCatalogue.builtin(node.getTag(), version).orElse(null);
        if (model == null) {
            return;
        }
        for (PortModel port : model.ports(version)) {
            if (port.name().equals(BuiltinNodes.ID)) {
                continue; // a cross-reference for subtrees: BtValidator's checkRegisteredId and checkSubtreeId
            }
            Attribute attribute = BtAttributes.find(node.getAttributes(), port.name());
            if (attribute == null) {
                if (port.required()) {
                    missing(node, port.name());
                }
            } else if (!isBlackboardPointer(attribute.getValue()) && !port.accepts(attribute.getValue())) {
                reportValue(port, attribute);
            }
        }
    }

    private void missing(TreeNode node, String port) {
        if (node instanceof Switch && port.equals(BuiltinNodes.VARIABLE)) {
            error(node.getTag() + " needs a variable attribute, e.g. variable=\"{choice}\"", node, BT.getTreeNode_Tag(),
                    SWITCH_WITHOUT_VARIABLE);
        } else {
            error(node.getTag() + " needs attribute " + port, node, BT.getTreeNode_Tag(),
                    node instanceof Switch ? SWITCH_MISSING_CASE : MISSING_ATTRIBUTE, port);
        }
    }

    private void reportValue(PortModel port, Attribute attribute) {
        String value = attribute.getValue();
        if (port.type().isInteger()) {
            if (!PortType.INT.accepts(value)) {
                error(port.name() + " must be an integer, not '" + value + "'", attribute, BT.getAttribute_Value(),
                        NOT_AN_INTEGER);
            } else {
                int minimum = port.minimum();
                error(port.name() + " must be at least " + minimum + ", not " + Integer.parseInt(value.trim()), attribute,
                        BT.getAttribute_Value(), INTEGER_TOO_SMALL, String.valueOf(minimum));
            }
        } else if (port.type() == PortType.BOOL) {
            error(port.name() + " must be true or false, not '" + value + "'", attribute, BT.getAttribute_Value(),
                    NOT_A_BOOLEAN);
        } else if (!port.values().isEmpty() && !value.isEmpty()) {
            // Empty, as Groot writes an unset port: BehaviorTree.CPP uses the default.
            error(port.name() + " must be " + oneOf(port.values()) + ", not '" + value + "'", attribute,
                    BT.getAttribute_Value(),
                    port.name().equals(BuiltinNodes.RETURN_ON_MISMATCH) ? BAD_RETURN_ON_MISMATCH : BAD_STATUS);
        }
    }

    private static String oneOf(List<String> values) {
        return String.join(", ", values.subList(0, values.size() - 1)) + " or " + values.get(values.size() - 1);
    }

    /**
     * Child counts, the same in both versions. Leaves with children are BtValidator's (an error or
     * a warning depending on the leaf).
     */
    @Check
    public void checkChildren(TreeNode node) {
        NodeModel model = node.getTag() == null || node instanceof LeafNode ? null
                : NodeCatalogue.find(node.getTag()).orElse(null);
        if (model == null) {
            return;
        }
        List<TreeNode> children = BtTrees.children(node);
        Children rule = model.children();
        if (rule.admits(children.size())) {
            return;
        }
        String tag = node.getTag();
        if (model.kind() == NodeKind.DECORATOR) {
            error(tag + " needs exactly one child, it has " + (children.isEmpty() ? "none" : children.size()),
                    children.size() > 1 ? children.get(1) : node, children.size() > 1 ? null : BT.getTreeNode_Tag(),
                    DECORATOR_CHILD_COUNT);
        } else if (children.isEmpty() && (rule.min() <= 1 || node instanceof Switch)) {
            error(tag + " needs at least one child", node, BT.getTreeNode_Tag(), CONTROL_WITHOUT_CHILDREN);
        } else if (node instanceof Switch) {
            int cases = rule.min() - 1;
            error(tag + " with " + cases + " cases needs " + rule.min()
                    + " children (one per case and a default last), it has " + children.size(), node,
                    BT.getTreeNode_Tag(), SWITCH_CHILD_COUNT);
        } else {
            // IfThenElse and WhileDoElse: a condition, a then-branch and an optional else-branch.
            boolean conditional = node instanceof IfThenElse || node instanceof WhileDoElse;
            String message = tag + " needs " + rule.describe() + " children"
                    + (conditional ? " (condition, then, optional else)" : "") + ", it has " + children.size();
            String code = conditional ? CONDITIONAL_CHILD_COUNT : CHILD_COUNT;
            if (children.size() < rule.min()) {
                error(message, node, BT.getTreeNode_Tag(), code);
            } else {
                error(message, children.get(rule.max()), null, code);
            }
        }
    }

    static boolean isBlackboardPointer(String value) {
        String trimmed = value.trim();
        return (trimmed.startsWith("{") || trimmed.startsWith("${")) && trimmed.endsWith("}");
    }
}
