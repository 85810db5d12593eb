package org.miron.runtime.roqme.expr;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.List;
import org.miron.runtime.roqme.model.RoqmeModel.Type;

/** Literal values of the runtime model, of {@code --param} texts and of {@code roqme.context} messages. */
public final class Literals {
    private Literals() {
    }

    static boolean isLiteral(JsonNode e) {
        return e.has("number") || e.has("boolean") || e.has("string") || e.has("enum") || e.has("time")
                || e.has("event") || e.has("sequence");
    }

    /** The value of a literal node (a sequence of literals as a list). */
    public static Object of(JsonNode e) {
        if (e.has("number")) {
            return e.get("number").asDouble();
        }
        if (e.has("time")) {
            return e.get("time").asDouble();
        }
        if (e.has("boolean")) {
            return e.get("boolean").asBoolean();
        }
        if (e.has("enum")) {
            return e.get("enum").asText();
        }
        if (e.has("string")) {
            return e.get("string").asText();
        }
        if (e.has("event")) {
            return Boolean.TRUE;
        }
        if (e.has("sequence")) {
            List<Object> l = new ArrayList<>();
            e.get("sequence").forEach(i -> l.add(of(i)));
            return l;
        }
        return null;
    }

    /** A {@code --param} text as a value of {@code type}, or null when it is not one. */
    static Object parse(String text, Type type, String id) {
        switch (type.kind()) {
            case "number", "time" -> {
                try {
                    double d = Double.parseDouble(text.trim());
                    return Double.isFinite(d) ? d : null;
                } catch (NumberFormatException e) {
                    return null;
                }
            }
            case "boolean" -> {
                return text.equals("true") ? Boolean.TRUE : text.equals("false") ? Boolean.FALSE : null;
            }
            case "enum" -> {
                String lit = literal(text);
                return type.literals() != null && type.literals().contains(lit) ? lit : null;
            }
            default -> {
                return null;
            }
        }
    }

    static String describe(Type type) {
        return "enum".equals(type.kind()) ? "literal of " + type.literals() : type.kind();
    }

    /** {@code AvailableSpace::HIGH} or {@code HIGH} → {@code HIGH}. */
    static String literal(String text) {
        int i = text.lastIndexOf("::");
        if (i >= 0) {
            return text.substring(i + 2);
        }
        i = text.lastIndexOf('.');
        return i >= 0 ? text.substring(i + 1) : text;
    }

    /**
     * A context message's {@code value} as a value of {@code type}, or null when it does not match
     * (a wrong type): numbers must be finite (and the array's length its cardinality), enum values a
     * declared literal name; an event takes any value.
     */
    public static Object fromMessage(JsonNode value, Type type) {
        if ("eventtype".equals(type.kind())) {
            return Boolean.TRUE;
        }
        if (type.cardinality() != null) {
            if (!value.isArray() || value.size() != type.cardinality()) {
                return null;
            }
            List<Object> l = new ArrayList<>();
            for (JsonNode i : value) {
                Object o = scalar(i, type);
                if (o == null) {
                    return null;
                }
                l.add(o);
            }
            return l;
        }
        return scalar(value, type);
    }

    private static Object scalar(JsonNode v, Type type) {
        return switch (type.kind()) {
            case "number", "time" -> v.isNumber() && Double.isFinite(v.asDouble()) ? (Object) v.asDouble() : null;
            case "boolean" -> v.isBoolean() ? (Object) v.asBoolean() : null;
            case "enum" -> {
                String lit = v.isTextual() ? literal(v.asText()) : null;
                yield lit != null && type.literals() != null && type.literals().contains(lit) ? lit : null;
            }
            default -> null;
        };
    }
}
