package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * A varpoint binding ({@code bt}, {@code arch} or {@code btport}); the remaining fields are read
 * from {@code raw} by whoever applies it.
 */
public record Binding(String type, JsonNode raw) {

    public String text(String field) {
        JsonNode n = raw.get(field);
        return n == null || n.isNull() ? null : n.asText();
    }
}
