package org.miron.generator.rules;

import com.fasterxml.jackson.databind.JsonNode;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.BoundedType;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EventType;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.util.Types;
import org.miron.generator.AdaptationModel;
import org.miron.generator.Names;

/**
 * The situations the rule check tries: per input a rule reads, one value per interval its
 * thresholds (the constants the rules compare it with) cut — just below the first, each threshold,
 * midway between two, just above the last; a metric stays in [0,1], a number context in its declared
 * range (lo:hi) — every literal of an enum, both
 * Booleans; all combinations, numbered in
 * mixed radix. Contexts are known (a rule over an unknown context does not apply). Also describes
 * a situation in the model's terms, an input by the interval of its thresholds it lies in.
 */
final class Situations {
    private static final double BELOW_ABOVE = 1e-6;

    /** One input the rules read. */
    private record Input(String param, String name, double[] candidates, double[] thresholds, List<String> literals,
            boolean bool) {
    }

    private final List<Input> inputs = new ArrayList<>();
    private final Map<String, Double> known = new LinkedHashMap<>();

    Situations(AdaptationModel m) {
        this(trees(m), m.properties, m.contexts);
    }

    private static List<JsonNode> trees(AdaptationModel m) {
        List<JsonNode> trees = new ArrayList<>();
        for (AdaptationModel.TranslatedRule r : m.rules) {
            trees.add(r.conditionTree());
            r.consequences().forEach(c -> trees.add(c.tree()));
        }
        return trees;
    }

    /**
     * The situations of the inputs these trees read, among these properties and contexts. A
     * number context's values stay in its declared range (lo:hi), as a metric's stay in [0,1]: a
     * condition beyond the range is false in every situation, as at run time.
     */
    Situations(List<JsonNode> trees, Collection<Property> properties, Collection<Context> contexts) {
        Map<String, TreeSet<Double>> thresholds = new LinkedHashMap<>();
        trees.forEach(t -> collect(t, thresholds));
        for (Property p : properties) {
            String param = Names.metric(p);
            if (thresholds.containsKey(param)) {
                TreeSet<Double> t = thresholds.get(param);
                TreeSet<Double> points = clamped(numbers(t), 0.0, 1.0); // an estimate is in [0,1]
                if (points.isEmpty()) {
                    points.add(0.5);
                }
                inputs.add(new Input(param, p.getName(), array(points), array(t), null, false));
            }
        }
        for (Context c : contexts) {
            String param = Names.context(c);
            known.put(Names.known(c), 1.0);
            if (!thresholds.containsKey(param)) {
                continue;
            }
            DataType type = Types.dataType((org.eclipse.emf.ecore.EObject) c);
            if (type instanceof EnumType e) {
                List<String> literals = e.getLiterals().stream().map(l -> l.getName()).toList();
                double[] all = new double[literals.size()];
                for (int i = 0; i < all.length; i++) {
                    all[i] = i;
                }
                inputs.add(new Input(param, c.getName(), all, new double[0], literals, false));
            } else if (type instanceof BooleanType || type instanceof EventType) {
                inputs.add(new Input(param, c.getName(), new double[] {0, 1}, new double[0], null, true));
            } else {
                TreeSet<Double> t = thresholds.get(param);
                BoundedType range = type instanceof BoundedType b ? b : null;
                Double lo = range == null ? null : range.getLower();
                Double hi = range == null ? null : range.getUpper();
                TreeSet<Double> points = clamped(numbers(t), lo, hi);
                if (points.isEmpty()) {
                    points.add(lo != null ? lo : hi != null ? Math.min(0.0, hi) : 0.0);
                }
                inputs.add(new Input(param, c.getName(), array(points), array(t), null, false));
            }
        }
    }

    /** Each point moved into [lo, hi] (an open end null): a point past an end stands for that end. */
    private static TreeSet<Double> clamped(TreeSet<Double> points, Double lo, Double hi) {
        TreeSet<Double> in = new TreeSet<>();
        for (double x : points) {
            in.add(Math.min(hi == null ? x : hi, Math.max(lo == null ? x : lo, x)));
        }
        return in;
    }

    /** Constants compared with each parameter, directly ({@code p < 0.3}); other parameters get an empty set. */
    private static void collect(JsonNode n, Map<String, TreeSet<Double>> into) {
        if (n == null) {
            return;
        }
        if (n.has("param")) {
            into.computeIfAbsent(n.get("param").asText(), k -> new TreeSet<>());
        }
        JsonNode args = n.path("args");
        if (args.size() == 2 && List.of("=", "!=", "<", ">", "<=", ">=").contains(n.path("op").asText())) {
            JsonNode a = args.get(0), b = args.get(1);
            if (a.has("param") && b.has("const") && b.get("const").isNumber()) {
                into.computeIfAbsent(a.get("param").asText(), k -> new TreeSet<>()).add(b.get("const").asDouble());
            } else if (b.has("param") && a.has("const") && a.get("const").isNumber()) {
                into.computeIfAbsent(b.get("param").asText(), k -> new TreeSet<>()).add(a.get("const").asDouble());
            }
        }
        args.forEach(x -> collect(x, into));
    }

    /**
     * One value per interval the thresholds cut: just below the first, each threshold, midway
     * between two, just above the last (a comparison with t is decided alike in each interval).
     */
    private static TreeSet<Double> numbers(TreeSet<Double> thresholds) {
        TreeSet<Double> points = new TreeSet<>();
        Double previous = null;
        for (double t : thresholds) {
            points.add(t);
            if (previous == null) {
                points.add(t - BELOW_ABOVE * Math.max(1, Math.abs(t)));
            } else {
                points.add((previous + t) / 2);
            }
            previous = t;
        }
        if (previous != null) {
            points.add(previous + BELOW_ABOVE * Math.max(1, Math.abs(previous)));
        }
        return points;
    }

    private static double[] array(TreeSet<Double> s) {
        return s.stream().mapToDouble(Double::doubleValue).toArray();
    }

    long count() {
        long n = 1;
        for (Input in : inputs) {
            if (n > Long.MAX_VALUE / in.candidates.length) {
                return Long.MAX_VALUE; // more than can ever be tried: the time budget cuts it
            }
            n *= in.candidates.length;
        }
        return n;
    }

    /** Situation number {@code s} (mixed radix over the inputs' candidates). */
    Map<String, Double> get(long s) {
        Map<String, Double> values = new LinkedHashMap<>(known);
        for (Input in : inputs) {
            int k = in.candidates.length;
            values.put(in.param, in.candidates[(int) (s % k)]);
            s /= k;
        }
        return values;
    }

    /** The situation's values of these parameters in the model's terms: "energy < 0.3 and occupancy = EMPTY". */
    String describe(Map<String, Double> situation, List<String> params) {
        List<String> parts = new ArrayList<>();
        for (String param : params) {
            for (Input in : inputs) {
                if (in.param.equals(param)) {
                    parts.add(describe(in, situation.get(param)));
                }
            }
        }
        if (parts.isEmpty()) {
            return "they both apply";
        }
        if (parts.size() == 1) {
            return parts.get(0);
        }
        return String.join(", ", parts.subList(0, parts.size() - 1)) + " and " + parts.get(parts.size() - 1);
    }

    private static String describe(Input in, double x) {
        if (in.literals != null) {
            return in.name + " = " + in.literals.get((int) x);
        }
        if (in.bool) {
            return x == 1 ? in.name : "not " + in.name;
        }
        Double below = null, above = null;
        for (double t : in.thresholds) {
            if (t == x) {
                return in.name + " = " + text(x);
            }
            if (t < x) {
                below = t;
            } else if (above == null) {
                above = t;
            }
        }
        if (below == null && above == null) {
            return in.name + " = " + text(x);
        }
        if (below == null) {
            return in.name + " < " + text(above);
        }
        if (above == null) {
            return in.name + " > " + text(below);
        }
        return text(below) + " < " + in.name + " < " + text(above);
    }

    private static String text(double x) {
        return BigDecimal.valueOf(x).stripTrailingZeros().toPlainString();
    }
}
