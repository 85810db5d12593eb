package org.miron.generator.rules;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EventType;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.util.Types;
import org.miron.generator.AdaptationModel;
import org.miron.generator.Names;
import org.miron.generator.SampledVariationPoint;

/**
 * Whether a requirement can be true and whether it can be false over the declared domains
 * (contexts' ranges, metrics in [0,1], varpoints' values): each temporal-free part of its formula
 * is evaluated as one expression in every situation {@link Situations} builds for it, combined with
 * every value of the varpoints it reads; the temporal operators keep what their operand can be (a
 * signal may hold any of its values for as long as it likes), not and never swap it, and, or and
 * implies combine the outcomes of independent parts. A part whose numbers are not all compared
 * directly with constants (arithmetic over inputs), or with too many combinations to try, is taken
 * as able to be both: the check only warns when it is sure.
 */
final class RequirementDomains {
    /** Past this many combinations a part is not tried. */
    static final long MAX_COMBINATIONS = 200_000;
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    /** What a formula can be. */
    record Outcomes(boolean canBeTrue, boolean canBeFalse) {
        static final Outcomes BOTH = new Outcomes(true, true);

        Outcomes not() {
            return new Outcomes(canBeFalse, canBeTrue);
        }

        Outcomes and(Outcomes o) {
            return new Outcomes(canBeTrue && o.canBeTrue, canBeFalse || o.canBeFalse);
        }

        Outcomes or(Outcomes o) {
            return not().and(o.not()).not();
        }
    }

    private final TreeEvaluator eval;
    private final Map<String, Integer> sizes = new HashMap<>();

    RequirementDomains(AdaptationModel m) {
        eval = TreeEvaluator.of(m.varpoints);
        for (SampledVariationPoint vp : m.varpoints) {
            sizes.put(vp.name, vp.size());
        }
    }

    Outcomes outcomes(AdaptationModel.TranslatedRequirement r) {
        List<Property> properties = new ArrayList<>();
        List<Context> contexts = new ArrayList<>();
        for (AdaptationModel.Signal s : r.reads()) {
            if (s.variable() instanceof Property p) {
                properties.add(p);
            } else if (s.variable() instanceof Context c) {
                contexts.add(c);
            }
        }
        return fold(r.formula(), properties, contexts);
    }

    private Outcomes fold(JsonNode f, List<Property> properties, List<Context> contexts) {
        JsonNode state = state(f);
        if (state != null) {
            return evaluate(state, properties, contexts);
        }
        JsonNode args = f.path("args");
        return switch (f.path("op").asText()) {
            case "not", "never" -> fold(args.get(0), properties, contexts).not();
            case "always", "eventually" -> fold(args.get(0), properties, contexts);
            case "and" -> fold(args.get(0), properties, contexts).and(fold(args.get(1), properties, contexts));
            case "or" -> fold(args.get(0), properties, contexts).or(fold(args.get(1), properties, contexts));
            case "implies" -> fold(args.get(0), properties, contexts).not().or(fold(args.get(1), properties, contexts));
            default -> Outcomes.BOTH;
        };
    }

    /** A temporal-free formula as one state expression (a implies b as not a or b); null when it has a temporal operator. */
    private static JsonNode state(JsonNode f) {
        if (f.has("state")) {
            return f.get("state");
        }
        String op = f.path("op").asText();
        List<JsonNode> args = new ArrayList<>();
        for (JsonNode a : f.path("args")) {
            JsonNode s = state(a);
            if (s == null) {
                return null;
            }
            args.add(s);
        }
        return switch (op) {
            case "not", "and", "or" -> op(op, args.toArray(new JsonNode[0]));
            case "implies" -> op("or", op("not", args.get(0)), args.get(1));
            default -> null;
        };
    }

    private Outcomes evaluate(JsonNode tree, List<Property> properties, List<Context> contexts) {
        Set<String> numeric = new LinkedHashSet<>();
        properties.forEach(p -> numeric.add(Names.metric(p)));
        for (Context c : contexts) {
            Object type = Types.dataType((org.eclipse.emf.ecore.EObject) c);
            if (!(type instanceof EnumType || type instanceof BooleanType || type instanceof EventType)) {
                numeric.add(Names.context(c));
            }
        }
        if (!decidable(tree, numeric)) {
            return Outcomes.BOTH;
        }
        Situations situations = new Situations(List.of(tree), properties, contexts);
        List<String> varpoints = new ArrayList<>(varpoints(tree, new LinkedHashSet<>()));
        long total = situations.count();
        for (String vp : varpoints) {
            total = total > MAX_COMBINATIONS ? total : total * sizes.get(vp);
        }
        if (total > MAX_COMBINATIONS) {
            return Outcomes.BOTH;
        }
        boolean canBeTrue = false, canBeFalse = false;
        for (long s = 0; s < situations.count(); s++) {
            Map<String, Double> in = situations.get(s);
            for (long k = 0; k < total / situations.count(); k++) {
                Map<String, Integer> assign = new HashMap<>();
                long rest = k;
                for (int v = 0; v < varpoints.size(); v++) {
                    int size = sizes.get(varpoints.get(v));
                    assign.put(varpoints.get(v), (int) (rest % size));
                    rest /= size;
                }
                if (eval.holds(tree, in, assign)) {
                    canBeTrue = true;
                } else {
                    canBeFalse = true;
                }
                if (canBeTrue && canBeFalse) {
                    return Outcomes.BOTH;
                }
            }
        }
        return new Outcomes(canBeTrue, canBeFalse);
    }

    /**
     * Whether every numeric input is read only as a direct operand of a comparison with a constant:
     * then Situations' points decide every comparison as all values of the input's domain do.
     */
    private static boolean decidable(JsonNode n, Set<String> numeric) {
        JsonNode args = n.path("args");
        if (args.size() == 2 && List.of("=", "!=", "<", ">", "<=", ">=").contains(n.path("op").asText())
                && (args.get(0).has("param") && args.get(1).has("const")
                        || args.get(1).has("param") && args.get(0).has("const"))) {
            return true;
        }
        if (n.has("param")) {
            return !numeric.contains(n.get("param").asText());
        }
        for (JsonNode a : args) {
            if (!decidable(a, numeric)) {
                return false;
            }
        }
        return true;
    }

    private static Set<String> varpoints(JsonNode n, Set<String> into) {
        if (n.has("index")) {
            into.add(n.get("index").asText());
        } else if (n.has("value")) {
            into.add(n.get("value").asText());
        }
        n.path("args").forEach(a -> varpoints(a, into));
        return into;
    }

    private static JsonNode op(String op, JsonNode... args) {
        ObjectNode node = JSON.objectNode().put("op", op);
        for (JsonNode a : args) {
            node.withArray("args").add(a);
        }
        return node;
    }
}
