package org.miron.runtime.bus;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A {@code roqme.context} message as every publisher writes it (docs/wire-formats.md):
 * {@code {"name", "namespace", "type", "value", "time"}}, the namespace left out when there is none
 * (a receiver treats a missing and an empty one alike). Publishers retain each context's latest
 * message under {@link #retainKey}, one key per subject, so a restarted broker gets it again.
 */
public final class ContextMessage {
    private ContextMessage() {
    }

    public static ObjectNode body(String name, String namespace, String type, JsonNode value, long time) {
        ObjectNode body = JsonNodeFactory.instance.objectNode().put("name", name);
        if (namespace != null && !namespace.isEmpty()) {
            body.put("namespace", namespace);
        }
        body.put("type", type);
        body.set("value", value);
        body.put("time", time);
        return body;
    }

    /** The key a publisher retains the latest message of a context under. */
    public static String retainKey(String namespace, String name) {
        return Topics.CONTEXT + "\0" + (namespace == null ? "" : namespace) + "\0" + name;
    }
}
