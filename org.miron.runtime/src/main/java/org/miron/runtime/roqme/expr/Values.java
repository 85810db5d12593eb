package org.miron.runtime.roqme.expr;

import java.util.List;
import java.util.Objects;

/** Value operators and functions of RoQME expressions: every one maps an unknown operand to unknown. */
final class Values {
    private Values() {
    }

    static ValueNode constant(Object v) {
        return s -> v;
    }

    static ValueNode ref(int slot) {
        return s -> s.values[slot];
    }

    static ValueNode not(ValueNode a) {
        return s -> a.eval(s) instanceof Boolean b ? !b : null;
    }

    static ValueNode neg(ValueNode a) {
        return s -> a.eval(s) instanceof Double d ? -d : null;
    }

    static ValueNode cond(ValueNode c, ValueNode t, ValueNode e) {
        return s -> c.eval(s) instanceof Boolean b ? (b ? t : e).eval(s) : null;
    }

    static ValueNode binary(String op, ValueNode l, ValueNode r) {
        return switch (op) {
            case "&" -> s -> {
                Object a = l.eval(s);
                Object b = r.eval(s);
                return a instanceof Boolean x && b instanceof Boolean y ? x && y : null;
            };
            case "|" -> s -> {
                Object a = l.eval(s);
                Object b = r.eval(s);
                return a instanceof Boolean x && b instanceof Boolean y ? x || y : null;
            };
            case "=" -> s -> eq(l.eval(s), r.eval(s));
            case "!=" -> s -> {
                Boolean e = eq(l.eval(s), r.eval(s));
                return e == null ? null : !e;
            };
            case "<" -> num(l, r, (a, b) -> a < b);
            case ">" -> num(l, r, (a, b) -> a > b);
            case "<=" -> num(l, r, (a, b) -> a <= b);
            case ">=" -> num(l, r, (a, b) -> a >= b);
            case "+" -> arith(l, r, Double::sum);
            case "-" -> arith(l, r, (a, b) -> a - b);
            case "*" -> arith(l, r, (a, b) -> a * b);
            case "/" -> arith(l, r, (a, b) -> a / b);
            default -> throw new IllegalArgumentException(op);
        };
    }

    private static Boolean eq(Object a, Object b) {
        if (a == null || b == null) {
            return null;
        }
        if (a instanceof Double x && b instanceof Double y) {
            return x.doubleValue() == y.doubleValue();
        }
        return a.equals(b);
    }

    interface Cmp {
        boolean test(double a, double b);
    }

    interface Op {
        double apply(double a, double b);
    }

    private static ValueNode num(ValueNode l, ValueNode r, Cmp c) {
        return s -> l.eval(s) instanceof Double a && r.eval(s) instanceof Double b ? c.test(a, b) : null;
    }

    private static ValueNode arith(ValueNode l, ValueNode r, Op o) {
        return s -> {
            if (l.eval(s) instanceof Double a && r.eval(s) instanceof Double b) {
                double v = o.apply(a, b);
                return Double.isNaN(v) ? null : v; // 0/0 and the like: undefined
            }
            return null;
        };
    }

    /** Functions on values (no window): maths and arrays; null when the name is not one of them. */
    static ValueNode function(String name, List<ValueNode> args) {
        ValueNode a = args.isEmpty() ? null : args.get(0);
        ValueNode b = args.size() > 1 ? args.get(1) : null;
        return switch (name) {
            case "pow" -> arith(a, b, Math::pow);
            case "sqrt" -> unary(a, Math::sqrt);
            case "exp" -> unary(a, Math::exp);
            case "abs" -> unary(a, Math::abs);
            case "first" -> s -> a.eval(s) instanceof List<?> l && !l.isEmpty() ? l.get(0) : null;
            case "last" -> s -> a.eval(s) instanceof List<?> l && !l.isEmpty() ? l.get(l.size() - 1) : null;
            case "size" -> s -> a.eval(s) instanceof List<?> l ? (Object) (double) l.size() : null;
            case "isEmpty" -> s -> a.eval(s) instanceof List<?> l ? (Object) l.isEmpty() : null;
            case "at" -> s -> {
                if (a.eval(s) instanceof List<?> l && b.eval(s) instanceof Double i) {
                    int k = (int) Math.floor(i);
                    return k >= 0 && k < l.size() ? l.get(k) : null;
                }
                return null;
            };
            case "includes" -> s -> {
                Object v = b.eval(s);
                return a.eval(s) instanceof List<?> l && v != null ? (Object) l.stream().anyMatch(x -> Objects.equals(eq(x, v), true)) : null;
            };
            case "avg", "min", "max", "sum", "count", "increasing", "decreasing", "stable" ->
                s -> a.eval(s) instanceof List<?> l ? aggregateList(name, l) : null;
            default -> null;
        };
    }

    private static ValueNode unary(ValueNode a, java.util.function.DoubleUnaryOperator f) {
        return s -> {
            if (a.eval(s) instanceof Double d) {
                double v = f.applyAsDouble(d);
                return Double.isNaN(v) ? null : v;
            }
            return null;
        };
    }

    private static Object aggregateList(String fn, List<?> l) {
        double[] v = new double[l.size()];
        for (int i = 0; i < v.length; i++) {
            if (!(l.get(i) instanceof Double d)) {
                return fn.equals("count") ? (Object) (double) l.size() : null;
            }
            v[i] = d;
        }
        return Aggregate.of(fn).apply(v, 0, v.length);
    }
}
