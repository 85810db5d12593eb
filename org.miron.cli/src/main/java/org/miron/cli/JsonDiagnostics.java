package org.miron.cli;

import org.miron.generator.standalone.Diagnostic;
import java.io.PrintWriter;
import java.util.List;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Diagnostics for tools: JSON Lines, one object per diagnostic and line, with the fields file,
 * line, column, endLine, endColumn (1-based, null when unknown; endColumn is just after the
 * problem), severity ("error" or "warning"), code (null for generator problems), message, and data
 * (an array of strings) when the issue has any.
 */
final class JsonDiagnostics {
    private static final ObjectMapper MAPPER = new ObjectMapper();

    private JsonDiagnostics() {
    }

    static void print(List<Diagnostic> diagnostics, PrintWriter out) {
        for (Diagnostic d : diagnostics) {
            out.println(toJson(d));
        }
    }

    static String toJson(Diagnostic d) {
        ObjectNode node = MAPPER.createObjectNode();
        node.put("file", d.file());
        node.put("line", position(d.line()));
        node.put("column", position(d.column()));
        node.put("endLine", position(d.endLine()));
        node.put("endColumn", position(d.endColumn()));
        node.put("severity", d.severity().toString());
        node.put("code", d.code());
        node.put("message", d.message());
        if (!d.data().isEmpty()) {
            ArrayNode data = node.putArray("data");
            d.data().forEach(data::add);
        }
        try {
            return MAPPER.writeValueAsString(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a tree of strings and numbers always serialises", e);
        }
    }

    private static Integer position(int value) {
        return value > 0 ? value : null;
    }
}
