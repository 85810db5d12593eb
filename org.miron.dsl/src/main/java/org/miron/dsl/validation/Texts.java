package org.miron.dsl.validation;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.roqme.BoundedType;

/** How numbers, ranges and elements are quoted in validation messages. */
final class Texts {

    private Texts() {
    }

    /** 10 rather than 10.0; 0.25 as is. */
    static String fmt(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? String.valueOf((long) d) : String.valueOf(d);
    }

    /** (lo:hi) as written in the model, with open bounds as -inf / +inf. */
    static String range(BoundedType t) {
        return "(" + (t.getLower() == null ? "-inf" : fmt(t.getLower())) + ":"
                + (t.getUpper() == null ? "+inf" : fmt(t.getUpper())) + ")";
    }

    /** The line of an element's name (not of its documentation comment). */
    static int line(EObject obj) {
        EStructuralFeature name = obj.eClass().getEStructuralFeature("name");
        List<INode> nodes = name == null ? List.of() : NodeModelUtils.findNodesForFeature(obj, name);
        INode node = nodes.isEmpty() ? NodeModelUtils.getNode(obj) : nodes.get(0);
        return node == null ? 0 : node.getStartLine();
    }

    /** The source text of an element. */
    static String text(EObject obj) {
        INode node = NodeModelUtils.getNode(obj);
        return node == null ? String.valueOf(EcoreUtil.getURI(obj)) : NodeModelUtils.getTokenText(node);
    }
}
