package org.miron.dds.config;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/**
 * A field path into a message: member names separated by dots, an index in brackets for a
 * sequence element ({@code header.stamp.sec}, {@code cell_voltage[0]}). Parsed into names (String)
 * and indices (Integer).
 */
public final class FieldPath {
    private FieldPath() {
    }

    /** The steps of {@code path}, or null when it is not one. */
    public static List<Object> parse(String path) {
        List<Object> steps = new ArrayList<>();
        for (String part : path.split("\\.", -1)) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("([A-Za-z_][A-Za-z0-9_]*)((?:\\[[0-9]{1,4}\\])*)").matcher(part);
            if (!m.matches()) {
                return null;
            }
            steps.add(m.group(1));
            java.util.regex.Matcher idx = java.util.regex.Pattern.compile("\\[([0-9]+)\\]").matcher(m.group(2));
            while (idx.find()) {
                steps.add(Integer.parseInt(idx.group(1)));
            }
        }
        return steps;
    }

    /** The value at the path in a message, or null when the message has no such field or element. */
    public static JsonNode resolve(JsonNode message, List<Object> path) {
        JsonNode n = message;
        for (Object step : path) {
            n = step instanceof Integer i ? (n.isArray() ? n.get(i) : null) : (n.isObject() ? n.get((String) step) : null);
            if (n == null) {
                return null;
            }
        }
        return n;
    }

    /**
     * The value at the path in a type's empty message: sequences are empty there, so an index
     * stands for "an element", typed as the sequence's... unknown element: a number is assumed, the
     * common case (cell_voltage[0]); the value itself is checked when a message arrives.
     */
    static JsonNode resolveTemplate(JsonNode template, List<Object> path) {
        JsonNode n = template;
        for (Object step : path) {
            if (step instanceof Integer) {
                if (!n.isArray()) {
                    return null;
                }
                n = n.size() > 0 ? n.get(0) : com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.numberNode(0.0);
            } else {
                n = n.isObject() ? n.get((String) step) : null;
                if (n == null) {
                    return null;
                }
            }
        }
        return n;
    }

    /** Sets the value at the path of a message (every step present); false when a step is missing. */
    static boolean set(JsonNode message, List<Object> path, JsonNode value) {
        JsonNode n = message;
        for (int i = 0; i < path.size() - 1; i++) {
            Object step = path.get(i);
            n = step instanceof Integer k ? (n.isArray() ? n.get(k) : null) : (n.isObject() ? n.get((String) step) : null);
            if (n == null) {
                return false;
            }
        }
        Object last = path.get(path.size() - 1);
        if (last instanceof Integer k) {
            if (!n.isArray() || k >= n.size()) {
                return false;
            }
            ((com.fasterxml.jackson.databind.node.ArrayNode) n).set(k, value);
            return true;
        }
        if (!n.isObject() || !n.has((String) last)) {
            return false;
        }
        ((com.fasterxml.jackson.databind.node.ObjectNode) n).set((String) last, value);
        return true;
    }

    /** Sets the value at the path of a copy of {@code base}. */
    public static com.fasterxml.jackson.databind.node.ObjectNode with(com.fasterxml.jackson.databind.node.ObjectNode base, List<Object> path,
            JsonNode value) {
        com.fasterxml.jackson.databind.node.ObjectNode copy = base.deepCopy();
        set(copy, path, value);
        return copy;
    }

    /** The value fields of a message, as paths, for an error message. */
    static String describe(JsonNode template) {
        List<String> out = new ArrayList<>();
        collect(template, "", out);
        return String.join(", ", out);
    }

    private static void collect(JsonNode n, String prefix, List<String> out) {
        for (Iterator<String> it = n.fieldNames(); it.hasNext();) {
            String k = it.next();
            JsonNode v = n.get(k);
            String p = prefix.isEmpty() ? k : prefix + "." + k;
            if (v.isObject()) {
                collect(v, p, out);
            } else {
                out.add(v.isArray() ? p + "[i]" : p);
            }
        }
    }
}
