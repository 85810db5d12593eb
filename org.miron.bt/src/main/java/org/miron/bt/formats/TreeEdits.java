package org.miron.bt.formats;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtAttributes;

/** Small edits of a BT model in place: attributes by name, a node turned into another class. */
final class TreeEdits {
    private TreeEdits() {
    }

    static Attribute attribute(String name, String value) {
        Attribute attribute = BtFactory.eINSTANCE.createAttribute();
        attribute.setName(name);
        attribute.setValue(value);
        return attribute;
    }

    static void rename(List<Attribute> attributes, String from, String to) {
        Attribute attribute = BtAttributes.find(attributes, from);
        if (attribute != null) {
            attribute.setName(to);
        }
    }

    static String remove(List<Attribute> attributes, String name) {
        Attribute attribute = BtAttributes.find(attributes, name);
        if (attribute == null) {
            return null;
        }
        attributes.remove(attribute);
        return attribute.getValue();
    }

    /** Sets an attribute, keeping its place if it exists, else appending it. */
    static void set(List<Attribute> attributes, String name, String value) {
        Attribute attribute = BtAttributes.find(attributes, name);
        if (attribute == null) {
            attributes.add(attribute(name, value));
        } else {
            attribute.setValue(value);
        }
    }

    /**
     * Replaces the node by a new node of another class with its tag, attributes and children,
     * recording the replacement (callers holding the old node look the new one up there).
     */
    static TreeNode become(TreeNode node, EClass eClass, String tag, Map<EObject, EObject> replacements) {
        TreeNode result = (TreeNode) BtFactory.eINSTANCE.create(eClass);
        result.setTag(tag);
        result.getAttributes().addAll(new ArrayList<>(node.getAttributes()));
        if (node instanceof DecoratorNode && result instanceof DecoratorNode) {
            ((DecoratorNode) result).setNode(((DecoratorNode) node).getNode());
            ((DecoratorNode) result).getSurplus().addAll(new ArrayList<>(((DecoratorNode) node).getSurplus()));
        } else if (node instanceof ControlNode && result instanceof ControlNode) {
            ((ControlNode) result).getNodes().addAll(new ArrayList<>(((ControlNode) node).getNodes()));
        } else if (node instanceof SubtreeNode && result instanceof SubtreeNode) {
            ((SubtreeNode) result).setBehaviorTree(((SubtreeNode) node).getBehaviorTree());
        }
        EcoreUtil.replace(node, result);
        replacements.put(node, result);
        return result;
    }

    static boolean isRemap(String value) {
        return value.startsWith("{") && value.endsWith("}") && !value.equals("{=}");
    }
}
