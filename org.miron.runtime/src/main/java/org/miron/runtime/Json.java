package org.miron.runtime;

import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The one shared Jackson mapper (thread-safe once configured) and small helpers. Every JSON read
 * of the runtime (bus bodies, skill requests and results, skill tables, scenarios, io.json) goes
 * through it. It rejects trailing tokens: by default Jackson stops after the first value, so
 * {@code {"value":0.2}xyz} would read as a valid estimate.
 */
public final class Json {
    public static final ObjectMapper MAPPER = JsonMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .build();

    private Json() {
    }

    public static ObjectNode object() {
        return MAPPER.createObjectNode();
    }

    /** Compact single-line JSON; never throws for trees built from Jackson nodes. */
    public static String write(Object value) {
        try {
            return MAPPER.writeValueAsString(value);
        } catch (Exception e) {
            throw new IllegalStateException("cannot serialise " + value, e);
        }
    }
}
