package org.miron.dds;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.config.BridgeConfig.ContextMapping;
import org.miron.dds.config.BridgeConfig.DecisionMapping;
import org.miron.dds.config.BridgeConfig.EstimateMapping;
import org.miron.dds.config.BridgeConfig.RoqmeTopics;
import org.miron.dds.transport.DdsException;
import org.miron.dds.transport.DdsTransport;
import org.miron.dds.transport.RosNames;
import org.miron.dds.transport.TopicSpec;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Bus;
import org.miron.runtime.bus.BusLink;
import org.miron.runtime.bus.Topics;

/**
 * The DDS / ROS 2 bridge ({@code miron dds-bridge}, docs/dds.md): ROS 2 topics and RoQME's own
 * context topics into {@code roqme.context}; {@code miron.decision} out to one ROS 2 topic per
 * varpoint (transient-local: a node that starts late gets the current value); {@code roqme.estimate}
 * out as {@code std_msgs/Float64} per metric and as {@code RoqmeEstimate}, or RoqmeEstimate in.
 *
 * <p>A sample that cannot be used (missing field, wrong type, NaN) is counted as
 * {@code malformedInput}, logged and dropped. DDS itself matches a peer that goes and comes back.
 * A restarted bridge loses no decision: the broker's last-value cache replays {@code miron.decision}
 * when it subscribes, and it writes the current values again.
 */
public final class Bridge implements AutoCloseable {
    /** The bridge's own status topic on the bus. */
    public static final String STATUS_TOPIC = "miron.dds.status";
    private static final Logger LOG = Logger.getLogger(Bridge.class.getName());
    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    private final BridgeConfig config;
    private final DdsTransport dds;
    private final Bus bus;
    private final BridgeCounters counters = new BridgeCounters();
    private final List<AutoCloseable> entities = new ArrayList<>();
    /** Per DDS topic name, how many remote endpoints each of our readers and writers on it has matched. */
    private final Map<String, List<java.util.function.IntSupplier>> matching = new java.util.concurrent.ConcurrentHashMap<>();
    /** By mapping (a varpoint may go to several topics); what each wrote last, under the bridge's lock. */
    private final Map<DecisionMapping, DdsTransport.Writer> decisionWriters = new java.util.IdentityHashMap<>();
    private final Map<DecisionMapping, JsonNode> lastDecision = new java.util.IdentityHashMap<>();
    private final List<DdsTransport.Writer> estimateWriters = new ArrayList<>();
    private DdsTransport.Writer roqmeEstimates;
    private final long statusIntervalMs;
    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "dds-bridge-status");
        t.setDaemon(true);
        return t;
    });

    private final String skillEndpoint;
    private ParameterAnswers answers;

    /** The bridge owns {@code dds} and closes it. */
    public Bridge(BridgeConfig config, DdsTransport dds, String busIn, String busOut, long statusIntervalMs) {
        this(config, dds, busIn, busOut, org.miron.runtime.Endpoints.DEFAULT_SKILL, statusIntervalMs);
    }

    /**
     * @param skillEndpoint where the skill interface's REP would be: the bridge answers the engine's
     *                      change-parameter queries there when a decision mapping names a {@code parameter}
     */
    public Bridge(BridgeConfig config, DdsTransport dds, String busIn, String busOut, String skillEndpoint, long statusIntervalMs) {
        this(config, dds, BusLink.sockets(busIn, busOut), skillEndpoint, statusIntervalMs);
    }

    /** The same, on a given bus link: sockets, or a broker's {@code local()} in this process. */
    public Bridge(BridgeConfig config, DdsTransport dds, BusLink link, String skillEndpoint, long statusIntervalMs) {
        this.config = config;
        this.skillEndpoint = skillEndpoint;
        this.dds = dds;
        this.statusIntervalMs = statusIntervalMs;
        List<String> subscriptions = new ArrayList<>();
        if (!config.decisions().isEmpty()) {
            subscriptions.add(Topics.DECISION);
        }
        if (!config.estimates().isEmpty() || (config.roqme() != null && config.roqme().estimates().equals("out"))) {
            subscriptions.add(Topics.ESTIMATE);
        }
        this.bus = link.open("dds-bridge", subscriptions, this::onBus);
    }

    /**
     * Creates the writers, connects to the bus (decisions and estimates flow from here on), then
     * creates the readers. Each DDS entity costs the library an XML profile round trip (about half
     * a second on a loaded machine), so the outputs come first.
     */
    public Bridge start() throws DdsException {
        long t0 = System.nanoTime();
        dds.onMatching(m -> LOG.info("dds-bridge: " + m));
        for (DecisionMapping d : config.decisions()) {
            DdsTransport.Writer w = track(RosNames.topic(d.topic()), dds.writer(new TopicSpec(RosNames.topic(d.topic()), d.type(), d.qos(), List.of())));
            decisionWriters.put(d, w);
        }
        for (EstimateMapping e : config.estimates()) {
            DdsTransport.Writer w = track(RosNames.topic(e.topic()), dds.writer(new TopicSpec(RosNames.topic(e.topic()), "std_msgs/Float64",
                    e.qos(), List.of())));
            estimateWriters.add(w);
        }
        RoqmeTopics r = config.roqme();
        TopicSpec est = r == null ? null : new TopicSpec("RoqmeEstimate", "RoqmeEstimate", r.qos(), List.of(r.partition()), r.keyed());
        if (r != null && r.estimates().equals("out")) {
            roqmeEstimates = track(est.name(), dds.writer(est));
        }
        bus.start();
        if (config.answersParameters()) {
            try {
                answers = new ParameterAnswers(skillEndpoint, this::parameter, counters);
            } catch (IllegalStateException e) {
                throw new DdsException(e.getMessage(), e);
            }
        }
        timer.scheduleAtFixedRate(this::publishStatus, 0, statusIntervalMs, TimeUnit.MILLISECONDS);
        for (ContextMapping c : config.contexts()) {
            TopicSpec spec = new TopicSpec(RosNames.topic(c.topic()), c.type(), c.qos(), List.of());
            track(spec.name(), dds.reader(spec, listener(spec.name(), msg -> ContextConversion.fromRos(c, msg, System.currentTimeMillis()))));
        }
        if (r != null) {
            for (String struct : r.contextTopics()) {
                TopicSpec spec = new TopicSpec(struct, struct, r.qos(), List.of(r.partition()), r.keyed());
                track(struct, dds.reader(spec, listener(struct, msg -> ContextConversion.fromRoqme(struct, r.namespace(), msg,
                        System.currentTimeMillis()))));
            }
            if (r.estimates().equals("in")) {
                track(est.name(), dds.reader(est, estimateListener(r.namespace())));
            }
        }
        LOG.info("dds-bridge: " + entities.size() + " DDS readers and writers ready in " + (System.nanoTime() - t0) / 1_000_000 + " ms");
        return this;
    }

    private DdsTransport.Writer track(String topic, DdsTransport.Writer w) {
        entities.add(w);
        matching.computeIfAbsent(topic, t -> new java.util.concurrent.CopyOnWriteArrayList<>()).add(w::matched);
        return w;
    }

    private void track(String topic, DdsTransport.Reader r) {
        entities.add(r);
        matching.computeIfAbsent(topic, t -> new java.util.concurrent.CopyOnWriteArrayList<>()).add(r::matched);
    }

    /**
     * The fewest remote endpoints any of the bridge's readers and writers on the DDS topic (as on
     * the wire: {@code rt/battery_state}, {@code RoqmeEstimate}) has matched now; 0 for a topic it does not use.
     */
    public int matched(String ddsTopic) {
        List<java.util.function.IntSupplier> l = matching.get(ddsTopic);
        return l == null ? 0 : l.stream().mapToInt(java.util.function.IntSupplier::getAsInt).min().orElse(0);
    }

    /** Converts a sample into a bus message body, or rejects it. */
    private interface Conversion {
        ObjectNode apply(ObjectNode message) throws Rejected;
    }

    private DdsTransport.Listener listener(String topic, Conversion conversion) {
        return new DdsTransport.Listener() {
            @Override
            public void sample(ObjectNode message) {
                try {
                    String body = conversion.apply(message).toString();
                    counters.add("contextsIn");
                    bus.publish(Topics.CONTEXT, body);
                } catch (Rejected e) {
                    malformed(topic, e.getMessage());
                }
            }

            @Override
            public void undecodable(String why) {
                malformed(topic, why);
            }
        };
    }

    private DdsTransport.Listener estimateListener(String namespace) {
        return new DdsTransport.Listener() {
            @Override
            public void sample(ObjectNode m) {
                String name = m.path("name").asText("");
                double v = m.path("value").asDouble(Double.NaN);
                if (!name.matches("[A-Za-z_][A-Za-z0-9_]*") || !(v >= 0 && v <= 1)) {
                    malformed("RoqmeEstimate", "estimate " + m + " needs an identifier name and a value in [0, 1]");
                    return;
                }
                counters.add("estimatesIn");
                ObjectNode b = F.objectNode().put("name", name);
                if (!namespace.isEmpty()) {
                    b.put("namespace", namespace);
                }
                bus.publish(Topics.ESTIMATE, b.put("value", v).put("time", System.currentTimeMillis()).toString());
            }

            @Override
            public void undecodable(String why) {
                malformed("RoqmeEstimate", why);
            }
        };
    }

    private void malformed(String topic, String why) {
        counters.add("malformedInput");
        counters.error("malformedInput", topic + ": " + why);
        LOG.warning("dds-bridge: dropped a sample on " + topic + ": " + why + " (" + counters.get("malformedInput") + " dropped so far)");
    }

    private void onBus(String topic, byte[] body) {
        JsonNode b;
        try {
            b = Json.MAPPER.readTree(body);
        } catch (java.io.IOException | RuntimeException e) {
            b = null;
        }
        if (b == null || !b.isObject()) {
            counters.add("badBusInput");
            LOG.warning("dds-bridge: dropped a malformed " + topic + " message");
            return;
        }
        if (topic.equals(Topics.DECISION)) {
            decision(b);
        } else if (topic.equals(Topics.ESTIMATE)) {
            estimate(b);
        }
    }

    /** Writes each mapped varpoint whose value changed since the last write. */
    private void decision(JsonNode body) {
        JsonNode decisions = body.path("decisions");
        long time = body.path("time").canConvertToLong() ? body.path("time").asLong() : System.currentTimeMillis();
        for (DecisionMapping d : config.decisions()) {
            JsonNode v = decisions.get(d.varpoint());
            if (v != null && !v.isNull()) {
                writeDecision(d, v, time);
            }
        }
    }

    /** A change-parameter query for {@code parameter}: written to its mapping's topic (if not already), false when none maps it. */
    private boolean parameter(String parameter, JsonNode value) {
        for (DecisionMapping d : config.decisions()) {
            if (parameter.equals(d.parameter())) {
                writeDecision(d, value, System.currentTimeMillis());
                return true;
            }
        }
        return false;
    }

    /**
     * Writes the decided value into the mapping's field (times its scale) of the mapping's base
     * message, the header stamped with the decision's time, unless that value was written last.
     * Called from the bus thread (miron.decision) and the change-parameter thread: one at a time.
     */
    private synchronized void writeDecision(DecisionMapping d, JsonNode decided, long timeMs) {
        JsonNode v = decided.isNumber() ? F.numberNode(decided.asDouble()) : decided;
        if (v.equals(lastDecision.get(d))) {
            return;
        }
        lastDecision.put(d, v);
        JsonNode data = DecisionConversion.value(d, decided);
        if (data == null) {
            counters.add("badBusInput");
            LOG.warning("dds-bridge: varpoint " + d.varpoint() + " decided " + decided + ", which " + d.field() + " of " + d.type() + " cannot carry");
            return;
        }
        write(decisionWriters.get(d), DecisionConversion.message(d, data, timeMs), "decisionsOut");
        LOG.info("dds-bridge: " + d.varpoint() + " = " + data + " in " + d.field() + " of " + d.type() + " on " + RosNames.topic(d.topic()));
    }

    private void estimate(JsonNode b) {
        String name = b.path("name").asText("");
        String ns = b.path("namespace").asText("");
        JsonNode v = b.path("value");
        if (!v.isNumber()) {
            counters.add("badBusInput");
            return;
        }
        for (int i = 0; i < config.estimates().size(); i++) {
            EstimateMapping e = config.estimates().get(i);
            if (e.metric().equals(name) && (e.namespace().isEmpty() || ns.isEmpty() || e.namespace().equals(ns))) {
                write(estimateWriters.get(i), v, "estimatesOut");
            }
        }
        if (roqmeEstimates != null) {
            try {
                roqmeEstimates.write(F.objectNode().put("name", name).set("value", v));
                counters.add("estimatesOut");
            } catch (RuntimeException ex) {
                LOG.warning("dds-bridge: cannot write RoqmeEstimate " + name + ": " + ex.getMessage());
            }
        }
    }

    private void write(DdsTransport.Writer w, JsonNode data, String counter) {
        write(w, F.objectNode().set("data", data), counter);
    }

    private void write(DdsTransport.Writer w, ObjectNode message, String counter) {
        try {
            w.write(message);
            counters.add(counter);
        } catch (RuntimeException e) {
            counters.error("ddsWrite", e.getMessage());
            LOG.warning("dds-bridge: " + e.getMessage());
        }
    }

    private void publishStatus() {
        ObjectNode s = F.objectNode().put("time", System.currentTimeMillis()).put("name", config.name()).put("state", "ok");
        s.set("counters", counters.json());
        if (counters.lastError() != null) {
            s.set("lastError", counters.lastError());
        }
        bus.publish(STATUS_TOPIC, s.toString());
    }

    /** Waits until the broker listens to the bridge's output. */
    public boolean awaitReady(long timeoutMs) throws InterruptedException {
        return bus.awaitReady(timeoutMs);
    }

    /** A counter of {@code miron.dds.status}: contextsIn, estimatesIn, decisionsOut, estimatesOut, parametersIn, queriesIgnored, malformedInput, badBusInput. */
    public long count(String name) {
        return counters.get(name);
    }

    @Override
    public void close() {
        timer.shutdownNow();
        if (answers != null) {
            answers.close();
        }
        bus.close();
        for (AutoCloseable e : entities) {
            try {
                e.close();
            } catch (Exception ignored) {
                // the participant goes next and takes what is left
            }
        }
        dds.close();
    }
}
