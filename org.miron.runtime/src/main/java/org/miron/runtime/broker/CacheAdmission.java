package org.miron.runtime.broker;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

/**
 * Decides whether a bus message may become the cached last value of its key. An invalid message
 * is still forwarded (subscribers count it as bad input), but it must never replace a valid
 * cached value: a restarted engine would get only the bad one and decide from its defaults.
 * The checks are the engine's, minus what needs the io.json: a RoQME estimate is an object with a
 * textual {@code name} and a finite number {@code value} in [0,1]; a context an object with a
 * textual {@code name} and a {@code value} matching its declared {@code type}; any other body
 * that looks like JSON must be exactly one JSON value. Non-JSON bodies of other topics are cached
 * by topic, as before.
 */
final class CacheAdmission {
    private CacheAdmission() {
    }

    /** Null when the message may be cached, otherwise why not. */
    static String reject(List<byte[]> frames) {
        String topic = new String(frames.get(0), StandardCharsets.ISO_8859_1);
        byte[] body = frames.size() > 1 ? frames.get(1) : new byte[0];
        boolean roqme = topic.equals(Topics.ESTIMATE) || topic.equals(Topics.CONTEXT);
        if (!roqme && !looksLikeJson(body)) {
            return null;
        }
        JsonNode json;
        try {
            json = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            return "not exactly one JSON value";
        }
        if (!roqme) {
            return null;
        }
        if (json == null || !json.isObject() || !json.path("name").isTextual()) {
            return "not an object with a 'name'";
        }
        JsonNode v = json.get("value");
        if (topic.equals(Topics.ESTIMATE)) {
            boolean ok = v != null && v.isNumber() && Double.isFinite(v.asDouble()) && v.asDouble() >= 0 && v.asDouble() <= 1;
            return ok ? null : "estimate value is not a number in [0,1]";
        }
        return contextValue(json.path("type").asText(""), v);
    }

    private static String contextValue(String type, JsonNode v) {
        if (v == null || v.isNull()) {
            return type.equals("event") ? null : "context without a value";
        }
        boolean ok = switch (type) {
            case "number" -> v.isNumber() && Double.isFinite(v.asDouble());
            case "boolean" -> v.isBoolean();
            case "enum" -> v.isTextual();
            case "event", "" -> true;
            default -> false;
        };
        return ok ? null : "context value does not match type '" + type + "'";
    }

    private static boolean looksLikeJson(byte[] body) {
        for (byte b : body) {
            if (b == '{' || b == '[') {
                return true;
            }
            if (b != ' ' && b != '\t' && b != '\r' && b != '\n') {
                return false;
            }
        }
        return false;
    }
}
