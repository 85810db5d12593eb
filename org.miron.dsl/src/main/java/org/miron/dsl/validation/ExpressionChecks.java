package org.miron.dsl.validation;

import static org.miron.dsl.validation.RoqmeIssueCodes.*;
import static org.miron.dsl.validation.Texts.text;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.validation.Check;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.ConditionalExpression;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.WhileExpression;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Formulas;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

/** Type checking of the operators and functions of RoQME expressions and patterns. */
public class ExpressionChecks extends CheckSet {

    private static final RoqmePackage R = RoqmePackage.eINSTANCE;
    /** Allowed argument counts of the built-in functions: {min, max}. */
    private static final Map<String, int[]> ARITY = new HashMap<>();
    static {
        for (String f : List.of("sqrt", "exp", "abs", "update", "period", "first", "last", "size", "isEmpty", "schedule")) {
            ARITY.put(f, new int[] { 1, 1 });
        }
        for (String f : List.of("avg", "min", "max", "count", "sum", "decreasing", "increasing", "stable", "eventWhen")) {
            ARITY.put(f, new int[] { 1, 2 });
        }
        for (String f : List.of("pow", "at", "includes")) {
            ARITY.put(f, new int[] { 2, 2 });
        }
    }

    /**
     * Inside a requirement an operand type error is the requirement's (miron.requirement-type, as
     * docs/issue-codes.md says), and an operator over a temporal formula is RequirementChecks' to
     * tell, once.
     */
    @Override
    protected void error(String message, EObject source, EStructuralFeature feature, String code, String... issueData) {
        if ((OPERAND_TYPE.equals(code) || INCOMPARABLE.equals(code)) && Formulas.requirementOf(source) != null) {
            if (source instanceof Expression x && !Formulas.isState(x)) {
                return;
            }
            code = MironIssueCodes.REQUIREMENT_TYPE;
        }
        super.error(message, source, feature, code, issueData);
    }

    @Check
    public void checkBinary(BinaryExpression e) {
        ExprType l = Types.typeOf(e.getLeft());
        ExprType r = Types.typeOf(e.getRight());
        String op = e.getOperator().getLiteral();
        switch (e.getOperator()) {
        case EQ:
        case NE:
            checkComparable(e, l, r, op);
            break;
        case LT:
        case GT:
        case LE:
        case GE:
            // booleans are ordered too (false < true): real models write "charging > false"
            if (l.kind == ExprType.Kind.BOOLEAN && r.kind == ExprType.Kind.BOOLEAN) {
                break;
            }
            if (!l.isNumeric()) {
                error("'" + op + "' needs numbers, but the left operand is " + l,
                        e, R.getBinaryExpression_Left(), OPERAND_TYPE);
            } else if (!r.isNumeric()) {
                error("'" + op + "' needs numbers, but the right operand is " + r,
                        e, R.getBinaryExpression_Right(), OPERAND_TYPE);
            }
            break;
        case PLUS:
        case MINUS:
        case TIMES:
        case DIVIDE:
            if (!l.isNumeric()) {
                error("'" + op + "' needs numbers, but the left operand is " + l,
                        e, R.getBinaryExpression_Left(), OPERAND_TYPE);
            } else if (!r.isNumeric()) {
                error("'" + op + "' needs numbers, but the right operand is " + r,
                        e, R.getBinaryExpression_Right(), OPERAND_TYPE);
            }
            break;
        case LOGICAL_AND:
        case LOGICAL_OR:
            if (!l.isLogical()) {
                error("'" + op + "' needs boolean or event operands, but the left one is " + l,
                        e, R.getBinaryExpression_Left(), OPERAND_TYPE);
            } else if (!r.isLogical()) {
                error("'" + op + "' needs boolean or event operands, but the right one is " + r,
                        e, R.getBinaryExpression_Right(), OPERAND_TYPE);
            }
            break;
        default: // event operators: or, and, ->
            if (!l.isEventLike()) {
                error("'" + op + "' needs events, booleans or enums, but the left operand is " + l,
                        e, R.getBinaryExpression_Left(), OPERAND_TYPE);
            } else if (!r.isEventLike()) {
                error("'" + op + "' needs events, booleans or enums, but the right operand is " + r,
                        e, R.getBinaryExpression_Right(), OPERAND_TYPE);
            }
        }
    }

    private void checkComparable(BinaryExpression e, ExprType l, ExprType r, String op) {
        if (l.comparableWith(r)) {
            return;
        }
        if (l.kind == ExprType.Kind.ENUM && r.kind == ExprType.Kind.ENUM) {
            Expression literalSide = e.getRight() instanceof EnumValue ? e.getRight() : e.getLeft();
            Expression other = literalSide == e.getRight() ? e.getLeft() : e.getRight();
            String literal = literalSide instanceof EnumValue ? text(literalSide) : "value of " + Types.typeOf(literalSide);
            error("cannot compare '" + text(other) + "' (" + Types.typeOf(other) + ") with '" + literal
                    + "', a literal of another enum (" + Types.typeOf(literalSide) + ")", e,
                    literalSide == e.getRight() ? R.getBinaryExpression_Right() : R.getBinaryExpression_Left(),
                    INCOMPARABLE);
        } else {
            error("cannot compare '" + text(e.getLeft()) + "' (" + l + ") with '" + text(e.getRight()) + "' (" + r
                    + ") using '" + op + "'", e, R.getBinaryExpression_Right(), OPERAND_TYPE);
        }
    }

    @Check
    public void checkUnary(UnaryExpression e) {
        ExprType t = Types.typeOf(e.getTerm());
        switch (e.getOperator()) {
        case MINUS:
            if (!t.isNumeric()) {
                error("'-' needs a number, not " + t, e, R.getUnaryExpression_Term(), OPERAND_TYPE);
            }
            break;
        case LOGICAL_NOT:
            if (!t.isLogical()) {
                error("'!' needs a boolean or event operand, not " + t, e, R.getUnaryExpression_Term(), OPERAND_TYPE);
            }
            break;
        default: // not, once
            if (!t.isEventLike()) {
                error("'" + e.getOperator().getLiteral() + "' needs an event, boolean or enum operand, not " + t, e,
                        R.getUnaryExpression_Term(), OPERAND_TYPE);
            }
        }
    }

    @Check
    public void checkConditional(ConditionalExpression e) {
        ExprType c = Types.typeOf(e.getCondition());
        if (!c.isLogical()) {
            error("the condition of '?:' must be boolean, not " + c, e, R.getConditionalExpression_Condition(), CONDITION_TYPE);
        }
        ExprType a = Types.typeOf(e.getIfTrue());
        ExprType b = Types.typeOf(e.getIfFalse());
        if (!a.comparableWith(b)) {
            error("both branches of '?:' must have the same type, not " + a + " and " + b, e,
                    R.getConditionalExpression_IfFalse(), BRANCH_TYPES);
        }
    }

    @Check
    public void checkWhile(WhileExpression e) {
        if (!Types.typeOf(e.getCondition()).isLogical()) {
            error("the condition of 'while' must be boolean, not " + Types.typeOf(e.getCondition()), e,
                    R.getWhileExpression_Condition(), CONDITION_TYPE);
        }
    }

    @Check
    public void checkRepeat(RepeatExpression e) {
        if (e.getTimes() <= 0) {
            error("repeat count must be positive, not " + e.getTimes() + " (in '" + Names.ownerName(e) + "')", e,
                    R.getRepeatExpression_Times(), REPEAT_COUNT);
        }
    }

    @Check
    public void checkRange(RangeExpression e) {
        if (e.getMin() > e.getMax()) {
            error("range(" + e.getMin() + ", " + e.getMax() + ") is empty: the minimum exceeds the maximum", e,
                    R.getRangeExpression_Min(), EMPTY_RANGE_EXPRESSION);
        }
    }

    @Check
    public void checkFunctionCall(FunctionCall call) {
        int[] arity = ARITY.get(call.getFunction());
        int n = call.getArgs().size();
        if (arity != null && (n < arity[0] || n > arity[1])) {
            String expected = arity[0] == arity[1] ? String.valueOf(arity[0]) : arity[0] + " or " + arity[1];
            error("function '" + call.getFunction() + "' takes " + expected + " argument(s), not " + n, call,
                    R.getFunctionCall_Function(), FUNCTION_ARITY);
        }
    }
}
