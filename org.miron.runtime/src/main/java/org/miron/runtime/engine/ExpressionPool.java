package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;
import java.util.Map;

/**
 * The rule expression trees of the io.json {@code decision} section, compiled once into flat
 * arrays (one slot per node) and evaluated without allocating. Every value is a double; booleans
 * are 1 and 0. Undefined arithmetic (division by zero, sqrt of a negative number, exp above 709,
 * pow outside its real domain: the .mzn's miron_* functions) is NaN, and
 * every comparison with NaN is false: MiniZinc's relational semantics, where an undefined
 * expression makes its nearest enclosing Boolean false. The requirement monitors
 * (org.miron.runtime.requirement) evaluate their state formulas, written in the same language, with it.
 */
public final class ExpressionPool {
    private static final int CONST = 0, PARAM = 1, INDEX = 2, VALUE = 3, OR = 4, AND = 5, NOT = 6, EQ = 7,
            NE = 8, LT = 9, GT = 10, LE = 11, GE = 12, ADD = 13, SUB = 14, MUL = 15, DIV = 16, NEG = 17, IF = 18,
            ABS = 19, SQRT = 20, EXP = 21, POW = 22, MIN = 23, MAX = 24;
    private static final List<String> OPS = List.of("const", "param", "index", "value", "or", "and", "not", "=",
            "!=", "<", ">", "<=", ">=", "+", "-", "*", "/", "neg", "if", "abs", "sqrt", "exp", "pow", "min", "max");
    private static final int[] ARITY = {0, 0, 0, 0, 2, 2, 1, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 1, 3, 1, 1, 1, 2, 2, 2};

    private int[] kind = new int[64];
    private int[] a = new int[64];
    private int[] b = new int[64];
    private int[] c = new int[64];
    private double[] constant = new double[64];
    private int size;

    private final Map<String, Integer> params;
    private final Map<String, Integer> varpoints;
    /** Per varpoint, its value table ({@code vp_x}). */
    private final double[][] values;

    /**
     * @param params    parameter name → slot in the array given to {@link #eval}
     * @param varpoints varpoint name → its position in the assignment array
     */
    public ExpressionPool(Map<String, Integer> params, Map<String, Integer> varpoints, double[][] values) {
        this.params = params;
        this.varpoints = varpoints;
        this.values = values;
    }

    /** Compiles a tree; returns its root. Varpoints it reads are added to {@code reads}. */
    public int compile(JsonNode n, BitSet reads) {
        if (n == null || !n.isObject()) {
            throw new IllegalArgumentException("expression " + n + " is not an object");
        }
        if (n.has("const")) {
            JsonNode v = n.get("const");
            if (!v.isNumber() && !v.isBoolean()) {
                throw new IllegalArgumentException("constant " + v + " is neither a number nor a boolean");
            }
            return add(CONST, -1, -1, -1, v.isBoolean() ? (v.asBoolean() ? 1 : 0) : v.asDouble());
        }
        if (n.has("param")) {
            Integer slot = params.get(n.get("param").asText());
            if (slot == null) {
                throw new IllegalArgumentException("unknown parameter '" + n.get("param").asText() + "'");
            }
            return add(PARAM, slot, -1, -1, 0);
        }
        if (n.has("index") || n.has("value")) {
            boolean index = n.has("index");
            String name = n.get(index ? "index" : "value").asText();
            Integer vp = varpoints.get(name);
            if (vp == null) {
                throw new IllegalArgumentException("unknown varpoint '" + name + "'");
            }
            reads.set(vp);
            return add(index ? INDEX : VALUE, vp, -1, -1, 0);
        }
        int op = OPS.indexOf(n.path("op").asText());
        JsonNode args = n.path("args");
        if (op < OR || args.size() != ARITY[op]) {
            throw new IllegalArgumentException("unknown operator or wrong argument count: " + n.path("op") + " with "
                    + args.size() + " arguments");
        }
        int x = compile(args.get(0), reads);
        int y = args.size() > 1 ? compile(args.get(1), reads) : -1;
        int z = args.size() > 2 ? compile(args.get(2), reads) : -1;
        return add(op, x, y, z, 0);
    }

    private int add(int k, int x, int y, int z, double value) {
        if (size == kind.length) {
            int n = size * 2;
            kind = Arrays.copyOf(kind, n);
            a = Arrays.copyOf(a, n);
            b = Arrays.copyOf(b, n);
            c = Arrays.copyOf(c, n);
            constant = Arrays.copyOf(constant, n);
        }
        kind[size] = k;
        a[size] = x;
        b[size] = y;
        c[size] = z;
        constant[size] = value;
        return size++;
    }

    /** True when the node evaluates to true (1) under the parameters and assignment. */
    public boolean holds(int node, double[] param, int[] assign) {
        return eval(node, param, assign) == 1;
    }

    public double eval(int node, double[] param, int[] assign) {
        switch (kind[node]) {
            case CONST:
                return constant[node];
            case PARAM:
                return param[a[node]];
            case INDEX:
                return assign[a[node]];
            case VALUE:
                return values[a[node]][assign[a[node]]];
            case OR:
                return truth(holds(a[node], param, assign) | holds(b[node], param, assign));
            case AND:
                return truth(holds(a[node], param, assign) & holds(b[node], param, assign));
            case NOT:
                return truth(!holds(a[node], param, assign));
            case IF:
                return holds(a[node], param, assign) ? eval(b[node], param, assign) : eval(c[node], param, assign);
            default:
                break;
        }
        double x = eval(a[node], param, assign);
        switch (kind[node]) {
            case NEG:
                return -x;
            case ABS:
                return Math.abs(x);
            case SQRT:
                return x < 0 ? Double.NaN : Math.sqrt(x);
            case EXP: // the .mzn's miron_exp: undefined where exp would overflow
                return x <= 709.0 ? Math.exp(x) : Double.NaN;
            default:
                break;
        }
        double y = eval(b[node], param, assign);
        switch (kind[node]) {
            case EQ:
                return truth(x == y);
            case NE: // NaN != NaN would be true in Java: undefined is false
                return truth(x != y && x == x && y == y);
            case LT:
                return truth(x < y);
            case GT:
                return truth(x > y);
            case LE:
                return truth(x <= y);
            case GE:
                return truth(x >= y);
            case ADD:
                return x + y;
            case SUB:
                return x - y;
            case MUL:
                return x * y;
            case DIV:
                return y == 0 ? Double.NaN : x / y;
            case POW: // the .mzn's miron_pow: undefined outside pow's real domain
                return x > 0 || (x == 0 && y >= 0) || (x < 0 && Math.abs(y) < 1e9 && y == Math.floor(y))
                        ? Math.pow(x, y) : Double.NaN;
            case MIN:
                return Math.min(x, y);
            case MAX:
                return Math.max(x, y);
            default:
                throw new IllegalStateException("operator " + kind[node]);
        }
    }

    private static double truth(boolean b) {
        return b ? 1 : 0;
    }
}
