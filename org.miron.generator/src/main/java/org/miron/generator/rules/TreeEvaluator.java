package org.miron.generator.rules;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Map;

/**
 * Evaluates the io.json's rule expression trees (docs/io-json.md, "decision") as the engine's
 * native backend does (its ExpressionPool, which the generator cannot depend on: the runtime is no
 * bundle of the Eclipse tooling): undefined arithmetic (division by zero, sqrt of a negative...)
 * is NaN, which makes the enclosing comparison false. Inputs are looked up by parameter name,
 * varpoints by name (their value index and their values).
 */
final class TreeEvaluator {
    private final Map<String, double[]> values;

    /** @param values per varpoint name, its values (an enum's are its indexes) */
    TreeEvaluator(Map<String, double[]> values) {
        this.values = values;
    }

    /** The evaluator of these varpoints' values (an enum's values are its indexes). */
    static TreeEvaluator of(java.util.List<org.miron.generator.SampledVariationPoint> varpoints) {
        Map<String, double[]> values = new java.util.HashMap<>();
        for (org.miron.generator.SampledVariationPoint vp : varpoints) {
            double[] v = new double[vp.size()];
            for (int i = 0; i < v.length; i++) {
                v[i] = vp.isEnum() ? i : vp.values.get(i).doubleValue();
            }
            values.put(vp.name, v);
        }
        return new TreeEvaluator(values);
    }

    boolean holds(JsonNode n, Map<String, Double> inputs, Map<String, Integer> assign) {
        return eval(n, inputs, assign) == 1;
    }

    double eval(JsonNode n, Map<String, Double> inputs, Map<String, Integer> assign) {
        if (n.has("const")) {
            JsonNode c = n.get("const");
            return c.isBoolean() ? truth(c.asBoolean()) : c.asDouble();
        } else if (n.has("param")) {
            Double x = inputs.get(n.get("param").asText());
            return x == null ? Double.NaN : x;
        } else if (n.has("index")) {
            return assign.get(n.get("index").asText());
        } else if (n.has("value")) {
            String vp = n.get("value").asText();
            return values.get(vp)[assign.get(vp)];
        }
        String op = n.path("op").asText();
        JsonNode args = n.path("args");
        switch (op) {
            case "or":
                return truth(holds(args.get(0), inputs, assign) | holds(args.get(1), inputs, assign));
            case "and":
                return truth(holds(args.get(0), inputs, assign) & holds(args.get(1), inputs, assign));
            case "not":
                return truth(!holds(args.get(0), inputs, assign));
            case "if":
                return holds(args.get(0), inputs, assign) ? eval(args.get(1), inputs, assign)
                        : eval(args.get(2), inputs, assign);
            default:
                break;
        }
        double x = eval(args.get(0), inputs, assign);
        switch (op) {
            case "neg":
                return -x;
            case "abs":
                return Math.abs(x);
            case "sqrt":
                return x < 0 ? Double.NaN : Math.sqrt(x);
            case "exp":
                return x <= 709.0 ? Math.exp(x) : Double.NaN;
            default:
                break;
        }
        double y = eval(args.get(1), inputs, assign);
        return switch (op) {
            case "=" -> truth(x == y);
            case "!=" -> truth(x != y && x == x && y == y);
            case "<" -> truth(x < y);
            case ">" -> truth(x > y);
            case "<=" -> truth(x <= y);
            case ">=" -> truth(x >= y);
            case "+" -> x + y;
            case "-" -> x - y;
            case "*" -> x * y;
            case "/" -> y == 0 ? Double.NaN : x / y;
            case "pow" -> x > 0 || (x == 0 && y >= 0) || (x < 0 && Math.abs(y) < 1e9 && y == Math.floor(y))
                    ? Math.pow(x, y) : Double.NaN;
            case "min" -> Math.min(x, y);
            case "max" -> Math.max(x, y);
            default -> throw new IllegalArgumentException("operator " + op);
        };
    }

    private static double truth(boolean b) {
        return b ? 1 : 0;
    }
}
