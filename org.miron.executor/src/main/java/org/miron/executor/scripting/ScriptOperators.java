package org.miron.executor.scripting;

import java.util.List;

import org.miron.bt.script.ast.AssignmentOperator;
import org.miron.bt.script.ast.BinaryOperator;
import org.miron.bt.script.ast.ComparisonOperator;
import org.miron.bt.script.ast.UnaryOperator;
import org.miron.executor.Blackboard;

/**
 * What the operators of the version-4 scripting language do, as BT.CPP 4 (operators.hpp):
 * arithmetic always yields a real; comparisons and logic yield 1.0 or 0.0; both sides of && and
 * || are evaluated; '..' joins text with text or numbers; '+' joins two texts; text compared with a
 * number is read as a number (true, false and enum names included); ':=' creates a key, '=' needs
 * an existing one; an assignment keeps the type an entry already has (an integer entry refuses a
 * fraction, a number entry reads text as a number).
 */
final class ScriptOperators {
    /** BT.CPP compares reals with float's epsilon. */
    private static final double EPSILON = Math.ulp(1.0f);

    private ScriptOperators() {
    }

    static Object read(ScriptScope scope, String name) {
        Integer enumValue = scope.enums().get(name);
        if (enumValue != null) {
            return (double) enumValue;
        }
        if (!scope.blackboard().contains(name)) {
            throw new ScriptException("Variable not found: " + name);
        }
        return ScriptValues.of(scope.blackboard().get(name)
                .orElseThrow(() -> new ScriptException("the blackboard entry [" + name + "] has no value yet")));
    }

    static Object unary(UnaryOperator operator, Object value) {
        if (!ScriptValues.isNumber(value)) {
            throw new ScriptException("operator " + operator.getLiteral() + " needs a number, not '" + value + "'");
        }
        double v = ScriptValues.toDouble(value);
        switch (operator) {
            case NEGATE:
                return -v;
            case COMPLEMENT:
                if (v > Long.MAX_VALUE || v < Long.MIN_VALUE) {
                    throw new ScriptException("Number out of range for bitwise operation");
                }
                return (double) ~(long) v;
            default:
                return v != 0 ? 0.0 : 1.0;
        }
    }

    static Object binary(BinaryOperator operator, Object left, Object right) {
        boolean numbers = ScriptValues.isNumber(left) && ScriptValues.isNumber(right);
        if (numbers) {
            double l = ScriptValues.toDouble(left);
            double r = ScriptValues.toDouble(right);
            switch (operator) {
                case PLUS:
                    return l + r;
                case MINUS:
                    return l - r;
                case TIMES:
                    return l * r;
                case DIV:
                    return l / r;
                case BIT_AND:
                case BIT_OR:
                case BIT_XOR:
                    return bitwise(operator, left, right);
                case LOGIC_AND:
                case LOGIC_OR:
                    return logic(operator, left, right);
                default:
                    throw new ScriptException("Operation not permitted: " + left + " " + operator.getLiteral() + " " + right);
            }
        }
        if (left instanceof String l && right instanceof String r && operator == BinaryOperator.PLUS) {
            return l + r;
        }
        if (operator == BinaryOperator.CONCAT && (left instanceof String || right instanceof String)) {
            return ScriptValues.toText(left) + ScriptValues.toText(right);
        }
        throw new ScriptException("Operation not permitted: '" + left + "' " + operator.getLiteral() + " '" + right + "'");
    }

    private static Object bitwise(BinaryOperator operator, Object left, Object right) {
        long l;
        long r;
        try {
            l = ScriptValues.toLong(left);
            r = ScriptValues.toLong(right);
        } catch (ScriptException e) {
            throw new ScriptException("Binary operators are not allowed if one of the operands is not an integer");
        }
        switch (operator) {
            case BIT_AND:
                return (double) (l & r);
            case BIT_OR:
                return (double) (l | r);
            default:
                return (double) (l ^ r);
        }
    }

    private static Object logic(BinaryOperator operator, Object left, Object right) {
        boolean l;
        boolean r;
        try {
            l = ScriptValues.toBoolean(left);
            r = ScriptValues.toBoolean(right);
        } catch (ScriptException e) {
            throw new ScriptException("Logic operators are not allowed if one of the operands is not castable to bool");
        }
        boolean result = operator == BinaryOperator.LOGIC_AND ? l && r : l || r;
        return result ? 1.0 : 0.0;
    }

    /** a op b op c ...: true (1.0) when every adjacent pair holds; stops at the first that does not. */
    static Object compareChain(ScriptScope scope, List<ComparisonOperator> operators, List<ScriptCode> operands) {
        Object left = operands.get(0).run(scope);
        for (int i = 0; i < operators.size(); i++) {
            Object right = operands.get(i + 1).run(scope);
            if (!compare(scope, operators.get(i), left, right)) {
                return 0.0;
            }
            left = right;
        }
        return 1.0;
    }

    private static boolean compare(ScriptScope scope, ComparisonOperator operator, Object left, Object right) {
        if (left instanceof String l && right instanceof String r) {
            int c = l.compareTo(r);
            return holds(operator, c == 0, c);
        }
        double l = left instanceof String s ? ScriptValues.textToDouble(s, scope.enums()) : ScriptValues.toDouble(left);
        double r = right instanceof String s ? ScriptValues.textToDouble(s, scope.enums()) : ScriptValues.toDouble(right);
        return holds(operator, Math.abs(l - r) <= EPSILON, Double.compare(l, r));
    }

    private static boolean holds(ComparisonOperator operator, boolean same, int order) {
        switch (operator) {
            case EQUAL:
                return same;
            case NOT_EQUAL:
                return !same;
            case LESS:
                return order < 0;
            case GREATER:
                return order > 0;
            case LESS_EQUAL:
                return order <= 0;
            default:
                return order >= 0;
        }
    }

    static Object assign(ScriptScope scope, String key, AssignmentOperator operator, ScriptCode valueCode) {
        Blackboard board = scope.blackboard();
        if (!board.contains(key)) {
            if (operator != AssignmentOperator.ASSIGN_CREATE) {
                throw new ScriptException("The blackboard entry [" + key + "] doesn't exist, yet. If you want to create a new one, "
                        + "use the operator [:=] instead of [=]");
            }
            board.declare(key);
        }
        Object value = valueCode.run(scope);
        Object current = board.get(key).map(ScriptValues::of).orElse(null);
        Object result;
        if (operator == AssignmentOperator.ASSIGN_CREATE || operator == AssignmentOperator.ASSIGN_EXISTING) {
            result = current == null ? value : keepType(key, current, value, scope);
        } else {
            if (current == null) {
                throw new ScriptException("The left operand of the operator [" + operator.getLiteral() + "] is not initialized");
            }
            result = keepType(key, current, combine(operator, current, value), scope);
        }
        board.set(key, result);
        return result;
    }

    private static Object combine(AssignmentOperator operator, Object current, Object value) {
        if (ScriptValues.isNumber(value)) {
            if (!ScriptValues.isNumber(current)) {
                throw new ScriptException("This Assignment operator can't be used with a non-numeric type");
            }
            double l = ScriptValues.toDouble(current);
            double r = ScriptValues.toDouble(value);
            switch (operator) {
                case ASSIGN_PLUS:
                    return l + r;
                case ASSIGN_MINUS:
                    return l - r;
                case ASSIGN_TIMES:
                    return l * r;
                default:
                    return l / r;
            }
        }
        if (operator == AssignmentOperator.ASSIGN_PLUS && current instanceof String text) {
            return text + value;
        }
        throw new ScriptException("Operator not supported for strings");
    }

    /** The new value converted to the type the entry has (BT.CPP's Any::copyInto and its string special case). */
    private static Object keepType(String key, Object current, Object value, ScriptScope scope) {
        if (current instanceof String) {
            if (value instanceof String) {
                return value;
            }
            throw new ScriptException("Error assigning a value to entry [" + key + "]: it holds text, not a number");
        }
        if (value instanceof String text) {
            return ScriptValues.textToDouble(text, scope.enums());
        }
        if (current instanceof Long) {
            try {
                return ScriptValues.toLong(value);
            } catch (ScriptException e) {
                throw new ScriptException("Error assigning a value to entry [" + key + "]: " + value + " is not an integer");
            }
        }
        return ScriptValues.toDouble(value);
    }
}
