package org.miron.runtime.roqme;

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
    private final CompiledModel model;

    public ContextDecoder(CompiledModel model) {
        this.model = model;
        for (Variable v : model.model().contexts()) {
            if (v.derived() == null || v.derived().isNull()) {
                byName.computeIfAbsent(v.name(), k -> new java.util.ArrayList<>()).add(v);
            }
        }
    }

    public Sample decode(byte[] body) throws BadContext {
        JsonNode n;
        try {
            n = Json.MAPPER.readTree(body);
        } catch (java.io.IOException e) {
            throw new BadContext(Problem.MALFORMED, "not JSON: " + firstLine(e.getMessage()));
        }
        return decode(n);
    }

    public Sample decode(JsonNode n) throws BadContext {
        if (n == null || !n.isObject() || !n.path("name").isTextual() || !n.has("value")) {
            throw new BadContext(Problem.MALFORMED, "a context needs an object with a textual name and a value");
        }
        Long time = null;
        if (n.has("time")) {
            if (!n.get("time").isNumber()) {
                throw new BadContext(Problem.MALFORMED, "time must be a number of ms");
            }
            time = n.get("time").asLong();
        }
        String name = n.get("name").asText();
        String ns = n.path("namespace").isTextual() ? n.get("namespace").asText() : "";
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
        if (v == null) {
            throw new BadContext(Problem.UNKNOWN, "unknown context " + (ns.isEmpty() ? "" : ns + ".") + name);
        }
        String type = n.path("type").asText("");
        String expected = "eventtype".equals(v.type().kind()) ? "event" : v.type().kind();
        if (!type.isEmpty() && !type.equals(expected) && !type.equals(v.type().kind())) {
            throw new BadContext(Problem.BAD_TYPE, "context " + name + " is a " + expected + ", the message says " + type);
        }
        Object value = Literals.fromMessage(n.get("value"), v.type());
        if (value == null) {
            throw new BadContext(Problem.BAD_TYPE, "context " + name + ": " + n.get("value") + " is not a valid "
                    + expected + (v.type().literals() != null ? " " + v.type().literals() : ""));
        }
        return new Sample(model.symbols().get(v.id()).slot(), value, time);
    }

    private static String firstLine(String s) {
        int i = s == null ? -1 : s.indexOf('\n');
        return i < 0 ? String.valueOf(s) : s.substring(0, i);
    }
}
