package org.miron.bt.script;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.script.ast.AstPackage;
import org.miron.bt.script.ast.Binary;
import org.miron.bt.script.ast.BinaryOperator;
import org.miron.bt.script.ast.Script;
import org.miron.bt.script.ast.Unary;
import org.miron.bt.script.ast.UnaryOperator;

/**
 * BT.CPP's grammar keeps arithmetic (+ - * / and prefix -), bitwise (&amp; | ^ and prefix ~ !) and
 * string (..) operators in separate groups: an expression uses one group, mixing needs
 * parentheses. The grammar here has one hierarchy, so mixing is found on the AST and reported as
 * a syntax error, at the outer operator.
 */
final class OperatorGroups {
    private enum Group { ARITHMETIC, BITWISE, STRING }

    private OperatorGroups() {
    }

    static void check(Script script, List<ScriptSyntaxError> errors) {
        for (EObject object : (Iterable<EObject>) () -> EcoreUtil.getAllContents(script, true)) {
            Group group = group(object);
            if (group == null) {
                continue;
            }
            for (EObject operand : object.eContents()) {
                Group inner = group(operand);
                if (inner != null && inner != group) {
                    errors.add(new ScriptSyntaxError(operatorOffset(object), operatorLength(object),
                            "operator cannot be mixed with previous operators: add parentheses"));
                    break;
                }
            }
        }
    }

    private static Group group(EObject object) {
        if (object instanceof Binary) {
            BinaryOperator operator = ((Binary) object).getOperator();
            switch (operator) {
            case PLUS: case MINUS: case TIMES: case DIV: return Group.ARITHMETIC;
            case BIT_AND: case BIT_OR: case BIT_XOR: return Group.BITWISE;
            case CONCAT: return Group.STRING;
            default: return null;
            }
        }
        if (object instanceof Unary) {
            return ((Unary) object).getOperator() == UnaryOperator.NEGATE ? Group.ARITHMETIC : Group.BITWISE;
        }
        return null;
    }

    private static INode operatorNode(EObject object) {
        EStructuralFeature feature = object instanceof Binary ? AstPackage.Literals.BINARY__OPERATOR
                : AstPackage.Literals.UNARY__OPERATOR;
        List<INode> nodes = NodeModelUtils.findNodesForFeature(object, feature);
        return nodes.isEmpty() ? NodeModelUtils.getNode(object) : nodes.get(0);
    }

    private static int operatorOffset(EObject object) {
        INode node = operatorNode(object);
        return node == null ? 0 : node.getOffset();
    }

    private static int operatorLength(EObject object) {
        INode node = operatorNode(object);
        return node == null ? 1 : Math.max(1, node.getLength());
    }

}
