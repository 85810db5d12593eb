package org.miron.runtime.roqme;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.Json;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Literals;
import org.miron.runtime.roqme.model.RoqmeModel.Variable;

/**
 * Turns a {@code roqme.context} body ({@code {"name","namespace","type","value","time"}}) into a
 * context slot and a value of its declared type. A context is matched by name, and by namespace too
 * when the message carries a non-empty one. Derived contexts are computed, never received.
 */
public final class ContextDecoder {
    /** Why a message was refused: the counter it goes to on the status topic. */
    public enum Problem { MALFORMED, UNKNOWN, BAD_TYPE }

    /** A refused message. */
    public static final class BadContext extends Exception {
        private static final long serialVersionUID = 1L;
        public final Problem problem;

        BadContext(Problem problem, String message) {
            super(message);
            this.problem = problem;
        }
    }

    /** A decoded sample; {@code time} is the message's time in ms, or null when absent. */
    public record Sample(int slot, Object value, Long time) {
    }

    private final Map<String, List<Variable>> byName = new HashMap<>();
    private final java.util.Set<String> derivedNames = new java.util.HashSet<>();
    private final CompiledModel model;

    public ContextDecoder(CompiledModel model) {
        this.model = model;
        for (Variable v : model.model().contexts()) {
            if (v.derived() == null || v.derived().isNull()) {
                byName.computeIfAbsent(v.name(), k -> new java.util.ArrayList<>()).add(v);
            } else {
                derivedNames.add(v.name());
            }
        }
    }

    /**
     * Whether a body names one of the model's derived contexts and says {@code "derived": true}: the
     * provider's own publication of a value it computes (see LiveProvider), which comes back to it
     * on the bus and in recordings. Not an input, and not an error either.
     */
    private boolean ownDerived(String name, boolean derivedFlag) {
        return derivedFlag && derivedNames.contains(name);
    }

    /**
     * Decodes a body; a streaming read (no tree): the replay decodes a trace line by line with it.
     * Null for the provider's own publication of a derived context (nothing to apply).
     */
    public Sample decode(byte[] body) throws BadContext {
        try (JsonParser p = Json.MAPPER.getFactory().createParser(body)) {
            return decode(p);
        } catch (java.io.IOException e) {
            throw new BadContext(Problem.MALFORMED, "not JSON: " + firstLine(e.getMessage()));
        }
    }

    public Sample decode(String body) throws BadContext {
        try (JsonParser p = Json.MAPPER.getFactory().createParser(body)) {
            return decode(p);
        } catch (java.io.IOException e) {
            throw new BadContext(Problem.MALFORMED, "not JSON: " + firstLine(e.getMessage()));
        }
    }

    private Sample decode(JsonParser p) throws java.io.IOException, BadContext {
        if (p.nextToken() != JsonToken.START_OBJECT) {
            throw new BadContext(Problem.MALFORMED, "a context must be a JSON object");
        }
        String name = null;
        String ns = "";
        String type = "";
        JsonNode value = null;
        Long time = null;
        boolean timeBad = false;
        boolean derivedFlag = false;
        String field;
        while ((field = p.nextFieldName()) != null) {
            JsonToken t = p.nextToken();
            switch (field) {
                case "name" -> name = t == JsonToken.VALUE_STRING ? p.getText() : null;
                case "namespace" -> ns = t == JsonToken.VALUE_STRING ? p.getText() : "";
                case "type" -> type = t == JsonToken.VALUE_STRING ? p.getText() : "";
                case "value" -> value = t.isScalarValue() ? scalar(p, t) : p.readValueAsTree();
                case "derived" -> derivedFlag = t == JsonToken.VALUE_TRUE;
                case "time" -> {
                    if (t.isNumeric()) {
                        time = p.getValueAsLong();
                    } else {
                        timeBad = true;
                    }
                }
                default -> p.skipChildren();
            }
        }
        if (p.nextToken() != null) {
            throw new BadContext(Problem.MALFORMED, "not JSON: trailing tokens after the object");
        }
        if (timeBad) {
            throw new BadContext(Problem.MALFORMED, "time must be a number of ms");
        }
        return ownDerived(name, derivedFlag) ? null : decode(name, ns, type, value, time);
    }

    private static JsonNode scalar(JsonParser p, JsonToken t) throws java.io.IOException {
        var f = Json.MAPPER.getNodeFactory();
        return switch (t) {
            case VALUE_NUMBER_INT -> f.numberNode(p.getLongValue());
            case VALUE_NUMBER_FLOAT -> f.numberNode(p.getDoubleValue());
            case VALUE_STRING -> f.textNode(p.getText());
            case VALUE_TRUE -> f.booleanNode(true);
            case VALUE_FALSE -> f.booleanNode(false);
            default -> f.nullNode();
        };
    }

    public Sample decode(JsonNode n) throws BadContext {
        if (n == null || !n.isObject()) {
            throw new BadContext(Problem.MALFORMED, "a context must be a JSON object");
        }
        if (n.has("time") && !n.get("time").isNumber()) {
            throw new BadContext(Problem.MALFORMED, "time must be a number of ms");
        }
        if (ownDerived(n.path("name").asText(""), n.path("derived").asBoolean(false))) {
            return null;
        }
        return decode(n.path("name").isTextual() ? n.get("name").asText() : null,
                n.path("namespace").isTextual() ? n.get("namespace").asText() : "", n.path("type").asText(""),
                n.get("value"), n.has("time") ? n.get("time").asLong() : null);
    }

    private Sample decode(String name, String ns, String type, JsonNode value, Long time) throws BadContext {
        if (name == null || value == null) {
            throw new BadContext(Problem.MALFORMED, "a context needs a textual name and a value");
        }
        List<Variable> candidates = byName.get(name);
        Variable v = null;
        if (candidates != null) {
            for (Variable c : candidates) {
                if (ns.isEmpty() || ns.equals(c.namespace())) {
                    v = c;
                    break;
                }
            }
        }
        if (v == null && derivedNames.contains(name)) {
            throw new BadContext(Problem.UNKNOWN, "context " + name + " is derived: the provider computes it, it is not an input");
        }
        if (v == null) {
            throw new BadContext(Problem.UNKNOWN, "unknown context " + (ns.isEmpty() ? "" : ns + ".") + name);
        }
        String expected = "eventtype".equals(v.type().kind()) ? "event" : v.type().kind();
        if (!type.isEmpty() && !type.equals(expected) && !type.equals(v.type().kind())) {
            throw new BadContext(Problem.BAD_TYPE, "context " + name + " is a " + expected + ", the message says " + type);
        }
        Object decoded = Literals.fromMessage(value, v.type());
        if (decoded == null) {
            throw new BadContext(Problem.BAD_TYPE, "context " + name + ": " + value + " is not a valid "
                    + expected + (v.type().literals() != null ? " " + v.type().literals() : ""));
        }
        return new Sample(model.symbols().get(v.id()).slot(), decoded, time);
    }

    private static String firstLine(String s) {
        int i = s == null ? -1 : s.indexOf('\n');
        return i < 0 ? String.valueOf(s) : s.substring(0, i);
    }
}
