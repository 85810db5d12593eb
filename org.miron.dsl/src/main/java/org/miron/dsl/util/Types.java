package org.miron.dsl.util;

import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.roqme.BeliefExpression;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.BooleanValue;
import org.miron.dsl.roqme.ConditionalExpression;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.DataTypeDeclaration;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.EventType;
import org.miron.dsl.roqme.EventValue;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.SequenceValue;
import org.miron.dsl.roqme.StringValue;
import org.miron.dsl.roqme.TimeType;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.Timer;
import org.miron.dsl.roqme.TypeReference;
import org.miron.dsl.roqme.TypedVariable;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.roqme.WhileExpression;

/** Static types of RoQME expressions, for the validators' type checks. */
public final class Types {

    private static final Set<String> NUMERIC_FUNCTIONS = Set.of("pow", "sqrt", "exp", "abs", "avg", "min", "max",
            "count", "sum", "size", "period");
    private static final Set<String> BOOLEAN_FUNCTIONS = Set.of("decreasing", "increasing", "stable", "isEmpty",
            "includes");
    private static final Set<String> EVENT_FUNCTIONS = Set.of("eventWhen", "update", "schedule");

    private Types() {
    }

    public static ExprType typeOf(Expression e) {
        if (e == null) {
            return ExprType.UNKNOWN;
        } else if (e instanceof BooleanValue) {
            return ExprType.BOOLEAN;
        } else if (e instanceof NumericValue) {
            return ExprType.NUMBER;
        } else if (e instanceof TimeValue) {
            return ExprType.TIME;
        } else if (e instanceof EventValue) {
            return ExprType.EVENT;
        } else if (e instanceof StringValue) {
            return ExprType.STRING;
        } else if (e instanceof EnumValue) {
            EnumLiteral literal = ((EnumValue) e).getLiteral();
            return literal == null || literal.eIsProxy() || !(literal.eContainer() instanceof EnumType)
                    ? ExprType.UNKNOWN : ExprType.enumOf((EnumType) literal.eContainer());
        } else if (e instanceof SequenceValue) {
            SequenceValue s = (SequenceValue) e;
            return s.getValues().isEmpty() ? ExprType.UNKNOWN : typeOf(s.getValues().get(0));
        } else if (e instanceof VariableRef) {
            return typeOf(((VariableRef) e).getVariable());
        } else if (e instanceof BeliefExpression) {
            return ExprType.NUMBER;
        } else if (e instanceof UnaryExpression) {
            UnaryExpression u = (UnaryExpression) e;
            switch (u.getOperator()) {
            case MINUS: {
                ExprType t = typeOf(u.getTerm());
                // a wrong operand is reported on the operator; unknown keeps it from being reported again
                return t.kind == ExprType.Kind.TIME ? ExprType.TIME : t.isNumeric() ? ExprType.NUMBER : ExprType.UNKNOWN;
            }
            default:
                return ExprType.BOOLEAN;
            }
        } else if (e instanceof BinaryExpression) {
            BinaryExpression b = (BinaryExpression) e;
            switch (b.getOperator()) {
            case PLUS:
            case MINUS:
            case TIMES:
            case DIVIDE:
                ExprType l = typeOf(b.getLeft());
                ExprType r = typeOf(b.getRight());
                if (!l.isNumeric() || !r.isNumeric()) {
                    return ExprType.UNKNOWN; // reported on the operator
                }
                return arithmetic(b.getOperator(), l.kind == ExprType.Kind.TIME, r.kind == ExprType.Kind.TIME);
            default:
                return ExprType.BOOLEAN;
            }
        } else if (e instanceof WhileExpression || e instanceof RepeatExpression || e instanceof RangeExpression
                || e instanceof org.miron.dsl.miron.TemporalExpression || e instanceof org.miron.dsl.miron.Implication) {
            return ExprType.BOOLEAN;
        } else if (e instanceof ConditionalExpression) {
            return typeOf(((ConditionalExpression) e).getIfTrue());
        } else if (e instanceof FunctionCall) {
            FunctionCall f = (FunctionCall) e;
            String fn = f.getFunction() == null ? "" : f.getFunction(); // null in a half-parsed x'
            if (NUMERIC_FUNCTIONS.contains(fn)) {
                return ExprType.NUMBER;
            } else if (BOOLEAN_FUNCTIONS.contains(fn)) {
                return ExprType.BOOLEAN;
            } else if (EVENT_FUNCTIONS.contains(fn)) {
                return ExprType.EVENT;
            } else if (!f.getArgs().isEmpty()) {
                return typeOf(f.getArgs().get(0)); // first, last, at: an element of the sequence
            }
        }
        return ExprType.UNKNOWN;
    }

    /** Times as physics has them: t + t, t - t, 2 * t and t / 2 are times; t / t is a number. */
    private static ExprType arithmetic(BinaryOperator op, boolean leftTime, boolean rightTime) {
        boolean time;
        switch (op) {
        case TIMES:
            time = leftTime != rightTime;
            break;
        case DIVIDE:
            time = leftTime && !rightTime;
            break;
        default:
            time = leftTime || rightTime;
        }
        return time ? ExprType.TIME : ExprType.NUMBER;
    }

    /** The type of the values a variable holds. */
    public static ExprType typeOf(Variable v) {
        if (v == null || v.eIsProxy()) {
            return ExprType.UNKNOWN;
        } else if (v instanceof TypedVariable) {
            return typeOf(((TypedVariable) v).getDeclaration());
        } else if (v instanceof Property && ((Property) v).getDeclaration() != null) {
            return typeOf(((Property) v).getDeclaration());
        } else if (v instanceof BeliefVariable) {
            return ExprType.NUMBER;
        } else if (v instanceof Timer) {
            return ExprType.EVENT; // a timer fires; its period is not a value
        }
        return ExprType.UNKNOWN;
    }

    public static ExprType typeOf(DataTypeDeclaration d) {
        DataType t = dataType(d);
        if (t instanceof BooleanType) {
            return ExprType.BOOLEAN;
        } else if (t instanceof EventType) {
            return ExprType.EVENT;
        } else if (t instanceof NumericType) {
            return ExprType.NUMBER;
        } else if (t instanceof TimeType) {
            return ExprType.TIME;
        } else if (t instanceof EnumType) {
            return ExprType.enumOf((EnumType) t);
        }
        return ExprType.UNKNOWN;
    }

    /** The data type behind a declaration, following a type reference; null when unresolved. */
    public static DataType dataType(DataTypeDeclaration d) {
        if (d instanceof DataType) {
            return (DataType) d;
        } else if (d instanceof TypeReference) {
            TypeReference ref = (TypeReference) d;
            return ref.getType() == null || ref.getType().eIsProxy() ? null : ref.getType().getType();
        }
        return null;
    }

    /** The declared data type of a variable, or null. */
    public static DataType dataType(EObject variable) {
        if (variable instanceof TypedVariable) {
            return dataType(((TypedVariable) variable).getDeclaration());
        } else if (variable instanceof Property) {
            return dataType(((Property) variable).getDeclaration());
        }
        return null;
    }
}
