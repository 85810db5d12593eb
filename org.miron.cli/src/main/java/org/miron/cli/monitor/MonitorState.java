package org.miron.cli.monitor;

import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.UnaryOperator;
import java.util.logging.Logger;

import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * What the live page shows, kept from the bus: the latest status of each node of the running tree,
 * the variation points' values and the metrics. Each change is handed to the subscribed pages as
 * one event; a page that (re)connects gets the whole state first. A malformed bus message is
 * logged, counted and dropped. A new {@code miron.bt.tree} (an executor that started or
 * restarted) clears the statuses: its nodes start idle.
 */
final class MonitorState {
    private static final Logger LOG = Logger.getLogger(MonitorState.class.getName());

    /** One server-sent event: its name and JSON data. */
    record Event(String name, String data) {
    }

    /** A connected page. */
    interface Subscriber {
        void send(Event event);
    }

    private final Map<String, String> statuses = new LinkedHashMap<>();
    private final Map<String, JsonNode> varpoints = new LinkedHashMap<>();
    private final Map<String, Double> metrics = new LinkedHashMap<>();
    /** The latest explanation of each varpoint's decision. */
    private final Map<String, JsonNode> explanations = new LinkedHashMap<>();
    /** The latest requirement events (miron.requirement), oldest first, at most {@link #REQUIREMENT_EVENTS}. */
    private final java.util.ArrayDeque<JsonNode> requirements = new java.util.ArrayDeque<>();
    static final int REQUIREMENT_EVENTS = 20;
    private final List<Subscriber> subscribers = new CopyOnWriteArrayList<>();
    private final AtomicLong rejected = new AtomicLong();
    private final UnaryOperator<String> metricName;
    private String tree;
    private long lastStatusSeq;

    /** @param metricName how the model names a metric, from an estimate's "namespace/name" */
    MonitorState(UnaryOperator<String> metricName) {
        this.metricName = metricName;
    }

    /** The bus handler: one message. */
    void onBus(String topic, byte[] body) {
        JsonNode message;
        try {
            message = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            message = null;
        }
        if (message == null || !message.isObject() || !accept(topic, message)) {
            rejected.incrementAndGet();
            LOG.warning("monitor: dropped a malformed message on " + topic);
        }
    }

    private boolean accept(String topic, JsonNode m) {
        if (topic.equals(Topics.BT_STATUS)) {
            String node = m.path("node").asText(null);
            String to = m.path("to").asText(null);
            if (node == null || to == null) {
                return false;
            }
            synchronized (this) {
                statuses.put(node, to);
                lastStatusSeq = m.path("seq").asLong();
            }
            broadcast(new Event("status", m.toString()));
        } else if (topic.equals(Topics.BT_TREE)) {
            synchronized (this) {
                statuses.clear();
                tree = m.path("tree").asText(null);
            }
            broadcast(new Event("reset", m.toString()));
        } else if (topic.startsWith(Topics.VARIANT_PREFIX) || topic.startsWith(Topics.BLACKBOARD_PREFIX)) {
            String vp = m.path("varpoint").asText(null);
            if (vp == null || !m.has("value")) {
                return false;
            }
            varpoint(vp, m.get("value"));
        } else if (topic.equals(Topics.DECISION)) {
            if (!m.path("decisions").isObject()) {
                return false;
            }
            m.path("decisions").fields().forEachRemaining(d -> varpoint(d.getKey(), d.getValue()));
            m.path("why").fields().forEachRemaining(w -> explanation(w.getKey(), m, w.getValue()));
        } else if (topic.equals(Topics.REQUIREMENT)) {
            if (!m.path("name").isTextual() || !m.path("verdict").isTextual() || !m.path("time").isNumber()) {
                return false;
            }
            synchronized (this) {
                requirements.addLast(m);
                if (requirements.size() > REQUIREMENT_EVENTS) {
                    requirements.removeFirst();
                }
            }
            broadcast(new Event("requirement", m.toString()));
        } else if (topic.equals(Topics.ESTIMATE)) {
            if (!m.path("name").isTextual() || !m.path("value").isNumber()) {
                return false;
            }
            String name = metricName.apply(m.path("namespace").asText("") + "/" + m.path("name").asText());
            double value = m.path("value").asDouble();
            synchronized (this) {
                if (Double.valueOf(value).equals(metrics.put(name, value))) {
                    return true;
                }
            }
            ObjectNode event = Json.MAPPER.createObjectNode().put("name", name).put("value", value);
            broadcast(new Event("metric", event.toString()));
        }
        return true;
    }

    private void varpoint(String name, JsonNode value) {
        synchronized (this) {
            if (value.equals(varpoints.put(name, value))) {
                return;
            }
        }
        ObjectNode event = Json.MAPPER.createObjectNode().put("name", name);
        event.set("value", value);
        broadcast(new Event("varpoint", event.toString()));
    }

    /**
     * Why the engine chose a varpoint's value ({@code miron.decision}'s {@code why}): the page shows
     * it on the variant Switch that the varpoint drives.
     */
    private void explanation(String vp, JsonNode decision, JsonNode why) {
        ObjectNode event = Json.MAPPER.createObjectNode().put("varpoint", vp);
        event.set("value", decision.path("decisions").path(vp));
        event.put("because", why.path("because").asText(""));
        event.set("rules", why.path("rules"));
        event.put("seq", decision.path("seq").asLong());
        synchronized (this) {
            explanations.put(vp, event);
        }
        broadcast(new Event("explanation", event.toString()));
    }

    private void broadcast(Event event) {
        subscribers.forEach(s -> s.send(event));
    }

    /** Hands an event that does not come from the bus (the debugger's) to every page. */
    void publish(Event event) {
        broadcast(event);
    }

    /** Subscribes a page: it gets the whole state at once, then every change. */
    void subscribe(Subscriber subscriber) {
        synchronized (this) {
            subscriber.send(new Event("snapshot", snapshot().toString()));
            subscribers.add(subscriber);
        }
    }

    void unsubscribe(Subscriber subscriber) {
        subscribers.remove(subscriber);
    }

    int subscribers() {
        return subscribers.size();
    }

    /** {"tree","statuses":{node: status},"varpoints":{},"metrics":{},"requirements":[event...],"explanations":{vp: event},"seq","rejected"} */
    synchronized ObjectNode snapshot() {
        ObjectNode state = Json.MAPPER.createObjectNode();
        state.put("tree", tree);
        ObjectNode s = state.putObject("statuses");
        statuses.forEach(s::put);
        ObjectNode v = state.putObject("varpoints");
        varpoints.forEach(v::set);
        ObjectNode mt = state.putObject("metrics");
        metrics.forEach(mt::put);
        requirements.forEach(state.putArray("requirements")::add);
        ObjectNode why = state.putObject("explanations");
        explanations.forEach(why::set);
        state.put("seq", lastStatusSeq);
        state.put("rejected", rejected.get());
        return state;
    }
}
