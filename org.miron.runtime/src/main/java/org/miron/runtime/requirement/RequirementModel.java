package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.miron.runtime.Json;

/**
 * The generated {@code name.requirements.json} (docs/requirements.md, its schema
 * docs/requirements.schema.json): the signals the requirements read and each requirement's formula.
 * Loading checks what the monitors rely on and names what is wrong; the formulas themselves are
 * checked when they are compiled ({@link RequirementMonitors}).
 */
public record RequirementModel(String model, List<Signal> signals, List<Requirement> requirements) {
    private static final List<String> KINDS = List.of("context", "property", "varpoint");
    private static final List<String> ROQME_TYPES = List.of("number", "boolean", "enum", "event");
    private static final List<String> VARPOINT_TYPES = List.of("enum", "number", "boolean");

    /**
     * A signal as the model names it.
     *
     * @param source   the RoQME context or property, or the varpoint, it is fed from
     * @param type     {@code number}/{@code boolean}/{@code enum}/{@code event} for a context,
     *                 {@code number} for a property, {@code enum}/{@code number}/{@code boolean} for a varpoint
     * @param literals an enum context's literals, a varpoint's values (as JSON), else empty
     * @param initial  a varpoint's index at start, or null
     * @param param    the parameter state expressions read a context or property by, null for a varpoint
     */
    public record Signal(String name, String kind, String source, String type, List<JsonNode> literals, Integer initial,
            String param) {
        public boolean isVarpoint() {
            return kind.equals("varpoint");
        }

        public boolean isEvent() {
            return kind.equals("context") && type.equals("event");
        }
    }

    /** A requirement; {@code probability} null unless it is probabilistic. */
    public record Requirement(String name, int line, int column, String text, Double probability, List<String> reads,
            JsonNode formula) {
    }

    public static RequirementModel load(Path file) {
        JsonNode root;
        try {
            root = Json.MAPPER.readTree(file.toFile());
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read " + file + ": " + e.getMessage(), e);
        }
        try {
            return parse(root);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
    }

    public static RequirementModel parse(JsonNode root) {
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("not a JSON object");
        }
        if (root.path("format").asInt(1) != 1) {
            throw new IllegalArgumentException("unsupported format " + root.get("format") + " (expected 1)");
        }
        List<Signal> signals = new ArrayList<>();
        Set<String> names = new HashSet<>();
        JsonNode s = array(root, "signals");
        for (int i = 0; i < s.size(); i++) {
            Signal sig = signal(s.get(i), "signals[" + i + "]");
            if (!names.add(sig.name())) {
                throw new IllegalArgumentException("signals[" + i + "]: signal '" + sig.name() + "' listed twice");
            }
            signals.add(sig);
        }
        List<Requirement> requirements = new ArrayList<>();
        JsonNode r = array(root, "requirements");
        for (int i = 0; i < r.size(); i++) {
            String where = "requirements[" + i + "]";
            JsonNode n = r.get(i);
            JsonNode p = n.path("probability");
            Double probability = p.isNumber() ? p.asDouble() : null;
            if (probability != null && !(probability > 0 && probability < 1)) {
                throw new IllegalArgumentException(where + ": probability " + probability + " is not in (0, 1)");
            }
            List<String> reads = new ArrayList<>();
            for (JsonNode x : n.path("reads")) {
                if (!names.contains(x.asText())) {
                    throw new IllegalArgumentException(where + ": reads '" + x.asText() + "', which is not a signal");
                }
                reads.add(x.asText());
            }
            if (!n.path("formula").isObject()) {
                throw new IllegalArgumentException(where + ": no formula");
            }
            requirements.add(new Requirement(text(n, "name", where), n.path("line").asInt(0), n.path("column").asInt(0),
                    n.path("text").asText(""), probability, List.copyOf(reads), n.get("formula")));
        }
        return new RequirementModel(root.path("model").asText("model"), List.copyOf(signals), List.copyOf(requirements));
    }

    private static Signal signal(JsonNode n, String where) {
        String kind = text(n, "kind", where);
        if (!KINDS.contains(kind)) {
            throw new IllegalArgumentException(where + ": kind '" + kind + "' is none of " + KINDS);
        }
        String name = text(n, "name", where);
        List<JsonNode> literals = new ArrayList<>();
        switch (kind) {
            case "context" -> {
                String type = text(n, "roqmeType", where);
                if (!ROQME_TYPES.contains(type)) {
                    throw new IllegalArgumentException(where + ": roqmeType '" + type + "' is none of " + ROQME_TYPES);
                }
                if (type.equals("enum")) {
                    n.path("literals").forEach(literals::add);
                    if (literals.isEmpty()) {
                        throw new IllegalArgumentException(where + ": an enum context without literals");
                    }
                }
                return new Signal(name, kind, text(n, "context", where), type, List.copyOf(literals), null, text(n, "param", where));
            }
            case "property" -> {
                return new Signal(name, kind, text(n, "property", where), "number", List.of(), null, text(n, "param", where));
            }
            default -> {
                String type = text(n, "type", where);
                if (!VARPOINT_TYPES.contains(type)) {
                    throw new IllegalArgumentException(where + ": type '" + type + "' is none of " + VARPOINT_TYPES);
                }
                n.path("values").forEach(literals::add);
                if (literals.isEmpty()) {
                    throw new IllegalArgumentException(where + ": a varpoint without values");
                }
                JsonNode init = n.path("initial");
                Integer initial = init.isInt() ? init.asInt() : null;
                if (initial != null && (initial < 0 || initial >= literals.size())) {
                    throw new IllegalArgumentException(where + ": initial " + initial + " indexes no value");
                }
                return new Signal(name, kind, text(n, "varpoint", where), type, List.copyOf(literals), initial, null);
            }
        }
    }

    private static JsonNode array(JsonNode root, String field) {
        JsonNode a = root.path(field);
        if (!a.isArray()) {
            throw new IllegalArgumentException("no '" + field + "' array");
        }
        return a;
    }

    private static String text(JsonNode n, String field, String where) {
        JsonNode v = n.path(field);
        if (!v.isTextual() || v.asText().isEmpty()) {
            throw new IllegalArgumentException(where + ": missing field '" + field + "'");
        }
        return v.asText();
    }
}
