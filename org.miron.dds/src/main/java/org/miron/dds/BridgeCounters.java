package org.miron.dds;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/** What the bridge counts, as {@code miron.dds.status} shows it; thread-safe. */
final class BridgeCounters {
    static final String[] NAMES = {"contextsIn", "estimatesIn", "decisionsOut", "estimatesOut", "parametersIn", "queriesIgnored",
        "malformedInput", "badBusInput"};
    private final Map<String, AtomicLong> counts = new ConcurrentHashMap<>();
    private volatile ObjectNode lastError;

    BridgeCounters() {
        for (String n : NAMES) {
            counts.put(n, new AtomicLong());
        }
    }

    void add(String name) {
        counts.get(name).incrementAndGet();
    }

    long get(String name) {
        return counts.get(name).get();
    }

    void error(String kind, String message) {
        lastError = JsonNodeFactory.instance.objectNode().put("kind", kind).put("message", message).put("time", System.currentTimeMillis());
    }

    ObjectNode json() {
        ObjectNode o = JsonNodeFactory.instance.objectNode();
        new TreeMap<>(counts).forEach((k, v) -> o.put(k, v.get()));
        return o;
    }

    ObjectNode lastError() {
        return lastError;
    }
}
