package org.miron.runtime.requirement;

import static org.junit.Assert.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.Test;

/**
 * The online monitors against the textbook definitions evaluated by brute force, instant by
 * instant, on random formulas over random traces: {@code eventually within D φ} at t is "φ at some
 * s in [t, t+D]" (OPEN when no s is and the window reaches past the end, or φ is OPEN at some s),
 * always and never through it, Kleene's connectives; a top-level always is watched as episodes.
 * Verdicts, violation counts and first violation instants must agree.
 */
public class RequirementOracleTest {
    private static final long[] BOUNDS = {0, 1, 3, 17, 60, 250, -1}; // -1: unbounded
    private static final String[] BOOLEANS = {"a", "b"};

    @Test
    public void randomFormulasOnRandomTracesAgreeWithTheDefinitions() {
        Random rnd = new Random(35);
        int compared = 0;
        for (int c = 0; c < 600; c++) {
            JsonNode f = c % 3 == 0 ? formula(rnd, 3) : Traces.always(formula(rnd, 2));
            int end = 40 + rnd.nextInt(400);
            double[][] trace = trace(rnd, end); // per signal (x, a, b), per instant; NaN: no value yet
            RequirementMonitors m = Traces.monitors(f);
            feed(m, trace, end, rnd);
            RequirementResult got = m.finish(end).get(0);
            Expected want = expected(f, trace, end);
            String what = "case " + c + ": " + f + " over " + end + " ms";
            assertEquals(what, want.verdict, got.verdict());
            assertEquals(what, want.violations, got.violations());
            if (want.first >= 0 && f.path("op").asText().equals("always")) {
                assertEquals(what, want.first, got.firstViolation().timeMs());
            }
            compared++;
        }
        assertEquals(600, compared);
    }

    private static JsonNode formula(Random rnd, int depth) {
        int k = depth == 0 ? rnd.nextInt(2) : rnd.nextInt(9);
        return switch (k) {
            case 0 -> Traces.x(rnd.nextBoolean() ? "<" : ">=", rnd.nextInt(10));
            case 1 -> Traces.is(BOOLEANS[rnd.nextInt(2)]);
            case 2 -> Traces.op("not", formula(rnd, depth - 1));
            case 3 -> Traces.op("and", formula(rnd, depth - 1), formula(rnd, depth - 1));
            case 4 -> Traces.op("or", formula(rnd, depth - 1), formula(rnd, depth - 1));
            case 5 -> Traces.implies(formula(rnd, depth - 1), formula(rnd, depth - 1));
            default -> Traces.temporal(new String[] {"always", "never", "eventually"}[k - 6], bound(rnd), formula(rnd, depth - 1));
        };
    }

    private static Long bound(Random rnd) {
        long b = BOUNDS[rnd.nextInt(BOUNDS.length)];
        return b < 0 ? null : b;
    }

    /** Values change at random instants, several at the same instant; x is unknown for a while at first. */
    private static double[][] trace(Random rnd, int end) {
        double[][] t = new double[3][end + 1];
        int xFrom = rnd.nextBoolean() ? 0 : rnd.nextInt(end / 4 + 1);
        double x = rnd.nextInt(10);
        boolean a = rnd.nextBoolean();
        boolean b = rnd.nextBoolean();
        for (int i = 0; i <= end; i++) {
            if (rnd.nextInt(12) == 0) {
                x = rnd.nextInt(10);
            }
            if (rnd.nextInt(15) == 0) {
                a = !a;
            }
            if (rnd.nextInt(9) == 0) {
                b = !b;
            }
            t[0][i] = i < xFrom ? Double.NaN : x;
            t[1][i] = a ? 1 : 0;
            t[2][i] = b ? 1 : 0;
        }
        return t;
    }

    /** Each instant's values, in a random order, repeated values too; sometimes time just advances. */
    private static void feed(RequirementMonitors m, double[][] trace, int end, Random rnd) {
        for (int i = 0; i <= end; i++) {
            List<Integer> order = new ArrayList<>(List.of(0, 1, 2));
            java.util.Collections.shuffle(order, rnd);
            for (int s : order) {
                boolean changed = i == 0 || Double.compare(trace[s][i], trace[s][i - 1]) != 0;
                if (Double.isNaN(trace[s][i]) || (!changed && rnd.nextInt(4) != 0)) {
                    continue;
                }
                if (s == 0) {
                    m.context(i, "x", trace[0][i]);
                } else {
                    m.context(i, s == 1 ? "a" : "b", trace[s][i] != 0);
                }
            }
            if (rnd.nextInt(20) == 0) {
                m.advance(i + 1);
            }
        }
    }

    private record Expected(Verdict verdict, int violations, long first) {
    }

    private static Expected expected(JsonNode f, double[][] trace, int end) {
        boolean xEver = false;
        for (double v : trace[0]) {
            xEver |= !Double.isNaN(v);
        }
        boolean readsX = f.toString().contains("param_x");
        String op = f.path("op").asText();
        Truth[] body;
        long until;
        if (op.equals("always") || op.equals("never")) {
            body = eval(f.get("args").get(0), trace, end);
            if (op.equals("never")) {
                body = not(body);
            }
            until = f.has("within") ? f.get("within").asLong() : Long.MAX_VALUE;
        } else {
            Truth v = eval(f, trace, end)[0];
            Verdict verdict = v == Truth.FALSE ? Verdict.VIOLATED : readsX && !xEver ? Verdict.NOT_EVALUATED
                    : v == Truth.OPEN ? Verdict.OPEN : Verdict.HOLDS;
            return new Expected(verdict, v == Truth.FALSE ? 1 : 0, -1);
        }
        int violations = 0;
        long first = -1;
        boolean in = false;
        boolean open = false;
        int xFrom = 0;
        while (xFrom <= end && readsX && Double.isNaN(trace[0][xFrom])) {
            xFrom++;
        }
        Truth[] finalBody = eval(f.get("args").get(0), trace, end, true);
        for (int t = 0; t <= end && t <= until; t++) {
            if (body[t] == Truth.FALSE && !in) {
                in = true;
                violations++;
                if (first < 0) {
                    first = t;
                }
            } else if (body[t] == Truth.TRUE) {
                in = false;
            } else if (body[t] == Truth.OPEN && t >= xFrom && finalBody[t] != Truth.OPEN) {
                open = true; // open because of the end, not because x had no value yet
            }
        }
        open |= until != Long.MAX_VALUE && until > end;
        Verdict verdict = violations > 0 ? Verdict.VIOLATED : readsX && !xEver ? Verdict.NOT_EVALUATED
                : open ? Verdict.OPEN : Verdict.HOLDS;
        return new Expected(verdict, violations, first);
    }

    private static Truth[] eval(JsonNode f, double[][] trace, int end) {
        return eval(f, trace, end, false);
    }

    /** {@code infinite}: as if the run went on for ever with its last values: what is OPEN only because of the end is not. */
    private static Truth[] eval(JsonNode f, double[][] trace, int end, boolean infinite) {
        int n = end + 1;
        Truth[] out = new Truth[n];
        if (f.has("state")) {
            for (int t = 0; t < n; t++) {
                out[t] = state(f.get("state"), trace, t);
            }
            return out;
        }
        String op = f.path("op").asText();
        JsonNode args = f.path("args");
        if (op.equals("not")) {
            return not(eval(args.get(0), trace, end, infinite));
        }
        if (op.equals("and") || op.equals("or") || op.equals("implies")) {
            Truth[] a = eval(args.get(0), trace, end, infinite);
            Truth[] b = eval(args.get(1), trace, end, infinite);
            for (int t = 0; t < n; t++) {
                out[t] = op.equals("and") ? a[t].and(b[t]) : op.equals("or") ? a[t].or(b[t]) : a[t].not().or(b[t]);
            }
            return out;
        }
        long d = f.has("within") ? f.get("within").asLong() : Long.MAX_VALUE / 4;
        Truth[] in = eval(args.get(0), trace, end, infinite);
        if (!op.equals("eventually")) {
            in = op.equals("always") ? not(in) : in;
        }
        for (int t = 0; t < n; t++) {
            Truth v = Truth.FALSE;
            for (long s = t; s <= Math.min(end, t + d); s++) {
                v = v.or(in[(int) s]);
            }
            if (v != Truth.TRUE && t + d > end && !infinite) {
                v = Truth.OPEN;
            }
            out[t] = v;
        }
        return op.equals("eventually") ? out : not(out);
    }

    private static Truth[] not(Truth[] a) {
        return Arrays.stream(a).map(Truth::not).toArray(Truth[]::new);
    }

    private static Truth state(JsonNode e, double[][] trace, int t) {
        if (e.has("param")) {
            String p = e.get("param").asText();
            double v = trace[p.equals("param_x") ? 0 : p.equals("param_a") ? 1 : 2][t];
            return Double.isNaN(v) ? Truth.OPEN : Truth.of(v != 0);
        }
        String op = e.get("op").asText();
        double x = trace[0][t];
        if (Double.isNaN(x)) {
            return Truth.OPEN;
        }
        double c = e.get("args").get(1).get("const").asDouble();
        return Truth.of(op.equals("<") ? x < c : x >= c);
    }
}
