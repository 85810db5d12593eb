package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.atomic.AtomicLong;
import org.miron.runtime.Json;
import org.miron.runtime.skill.RequestSender;

/**
 * Sends change-parameter queries for arch-bound varpoints off the solve loop, through a
 * {@link RequestSender}: per parameter only the latest wanted value is kept, each query waits for
 * its ack and is retried with back-off.
 */
public final class ParameterSender implements AutoCloseable {
    /** Progress reports, called on the sender thread. */
    public interface Listener extends RequestSender.Listener {
    }

    private final RequestSender sender;
    private final AtomicLong nextId = new AtomicLong(1);

    public ParameterSender(String endpoint, long ackTimeoutMs, long backoffMinMs, long backoffMaxMs, Listener listener) {
        this.sender = new RequestSender(endpoint, "engine-parameters", ackTimeoutMs, backoffMinMs, backoffMaxMs,
                listener);
    }

    public ParameterSender start() {
        sender.start();
        return this;
    }

    /**
     * Builds the SmartSoft change-parameter query body (without id) for an arch binding. Numbers
     * are sent as doubles, never truncated; a boolean as JSON true/false (a SmartSoft Boolean
     * parameter's value, never 0/1); anything else (an enum literal) as it is.
     */
    public static ObjectNode changeParameter(Binding arch, JsonNode value) {
        ObjectNode q = Json.object();
        q.put("type", "change-parameter");
        q.put("ParameterSetRepository", arch.text("parameterSetRepository"));
        q.put("ParameterSet", arch.text("parameterSet"));
        q.put("Component", arch.text("component"));
        q.put("Parameter", arch.text("parameter"));
        ObjectNode values = q.putObject("values");
        // As the original MIRoN query: the value in both slots of the parameter (e.g. min and max).
        JsonNode v = value.isNumber() ? DoubleNode.valueOf(value.asDouble()) : value;
        values.set("1", v);
        values.set("2", v);
        return q;
    }

    /** Queues a query for {@code key} (e.g. the varpoint), replacing any not yet acknowledged one. */
    public void submit(String key, ObjectNode query) {
        ObjectNode message = Json.object();
        message.put("id", nextId.getAndIncrement());
        message.put("msg-type", "query");
        message.set("query", query);
        sender.submit(key, message);
    }

    @Override
    public void close() {
        sender.close();
    }
}
