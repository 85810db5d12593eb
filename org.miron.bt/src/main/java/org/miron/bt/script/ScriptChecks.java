package org.miron.bt.script;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.script.ast.Assignment;
import org.miron.bt.script.ast.Binary;
import org.miron.bt.script.ast.BinaryOperator;
import org.miron.bt.script.ast.Expression;
import org.miron.bt.script.ast.Name;
import org.miron.bt.script.ast.NumberLiteral;
import org.miron.bt.script.ast.StringLiteral;
import org.miron.bt.script.ast.Unary;
import org.miron.bt.validation.BtIssueCodes;

/**
 * Script mistakes BT.CPP only finds when it ticks the node (it parses them fine): an assignment to
 * something that is not a blackboard key, a string literal in arithmetic or logic ("Operation not
 * permitted"). Found on the AST of a script without syntax errors.
 */
public final class ScriptChecks {
    /** One finding: offset and length in the script text, message and issue code (BtIssueCodes). */
    public static final class Finding {
        public final int offset;
        public final int length;
        public final String message;
        public final String code;

        Finding(EObject at, String message, String code) {
            INode node = NodeModelUtils.getNode(at);
            this.offset = node == null ? 0 : node.getOffset();
            this.length = node == null ? 1 : Math.max(1, node.getLength());
            this.message = message;
            this.code = code;
        }
    }

    private ScriptChecks() {
    }

    public static List<Finding> check(ParsedScript parsed) {
        List<Finding> findings = new ArrayList<>();
        if (parsed.hasErrors()) {
            return findings;
        }
        for (EObject object : (Iterable<EObject>) () -> EcoreUtil.getAllContents(parsed.getScript(), true)) {
            if (object instanceof Assignment && !(((Assignment) object).getTarget() instanceof Name)) {
                findings.add(new Finding(((Assignment) object).getTarget(), "the left side of "
                        + ((Assignment) object).getOperator().getLiteral()
                        + " must be a blackboard key", BtIssueCodes.SCRIPT_ASSIGNMENT_TARGET));
            } else if (object instanceof Binary) {
                checkOperands((Binary) object, findings);
            } else if (object instanceof Unary && ((Unary) object).getOperand() instanceof StringLiteral) {
                findings.add(new Finding(object, "operator " + ((Unary) object).getOperator().getLiteral()
                        + " cannot apply to a string", BtIssueCodes.SCRIPT_TYPE_MISMATCH));
            }
        }
        return findings;
    }

    private static void checkOperands(Binary binary, List<Finding> findings) {
        BinaryOperator operator = binary.getOperator();
        boolean numeric = operator == BinaryOperator.MINUS || operator == BinaryOperator.TIMES
                || operator == BinaryOperator.DIV || operator == BinaryOperator.BIT_AND
                || operator == BinaryOperator.BIT_OR || operator == BinaryOperator.BIT_XOR
                || operator == BinaryOperator.LOGIC_AND || operator == BinaryOperator.LOGIC_OR;
        // + joins two strings, but not a string and a number.
        boolean mixedPlus = operator == BinaryOperator.PLUS && (isString(binary.getLeft()) && isNumber(binary.getRight())
                || isNumber(binary.getLeft()) && isString(binary.getRight()));
        if (numeric && (isString(binary.getLeft()) || isString(binary.getRight())) || mixedPlus) {
            findings.add(new Finding(binary, "operator " + operator.getLiteral() + " cannot apply to a string"
                    + (operator == BinaryOperator.PLUS ? " and a number (.. concatenates)" : ""),
                    BtIssueCodes.SCRIPT_TYPE_MISMATCH));
        }
    }

    private static boolean isString(Expression expression) {
        return expression instanceof StringLiteral;
    }

    private static boolean isNumber(Expression expression) {
        return expression instanceof NumberLiteral;
    }
}
