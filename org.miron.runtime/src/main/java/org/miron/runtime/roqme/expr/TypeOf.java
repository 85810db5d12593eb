package org.miron.runtime.roqme.expr;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Map;

/** The type of an expression node for the compiler: what decides between a value and an event. */
final class TypeOf {
    private TypeOf() {
    }

    /** A reference's declared type; else the checker's static type ({@code "type"}), or one inferred when absent. */
    static String of(JsonNode e, Map<String, Symbol> symbols) {
        if (e.has("ref") && symbols.containsKey(e.get("ref").asText())) {
            return symbols.get(e.get("ref").asText()).valueType(); // the declaration knows best
        }
        String t = e.path("type").asText(null);
        if (t != null && !t.equals("unknown")) {
            return t;
        }
        String op = e.path("op").asText("");
        if (List.of("!", "&", "|", "=", "!=", "<", ">", "<=", ">=").contains(op)) {
            return "boolean";
        }
        if (List.of("and", "or", "->", "once", "not", "while", "repeat", "range").contains(op)) {
            return "event";
        }
        String fn = e.path("call").asText("");
        if (List.of("eventWhen", "update", "schedule").contains(fn)) {
            return "event";
        }
        if (List.of("increasing", "decreasing", "stable", "isEmpty", "includes").contains(fn) || e.has("boolean")) {
            return "boolean";
        }
        return e.has("enum") ? "enum" : e.has("event") ? "event" : "number";
    }
}
