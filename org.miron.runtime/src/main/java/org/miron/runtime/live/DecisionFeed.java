package org.miron.runtime.live;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.List;
import java.util.logging.Logger;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;

/**
 * Feeds the engine's decisions on the bus to a running BT executor: {@code miron.variant.<vp>}
 * values go to the variant source that VariantAction nodes read, {@code miron.blackboard.<vp>}
 * numbers and booleans to the source the tree copies into its blackboard before each tick. An executor that
 * starts late still gets the current decisions, from the broker's last-value cache.
 */
public final class DecisionFeed implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(DecisionFeed.class.getName());

    private final VariantSource variants;
    private final VariantSource blackboard;
    private final BusClient bus;
    private volatile long rejected;

    public DecisionFeed(String busIn, String busOut, VariantSource variants, VariantSource blackboard) {
        this.variants = variants;
        this.blackboard = blackboard;
        this.bus = new BusClient("executor", busIn, busOut,
                List.of(Topics.VARIANT_PREFIX, Topics.BLACKBOARD_PREFIX), this::onMessage);
    }

    public DecisionFeed start() {
        bus.start();
        return this;
    }

    void onMessage(String topic, byte[] body) {
        JsonNode message;
        try {
            message = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            message = null;
        }
        String varpoint = message == null ? null : message.path("varpoint").asText(null);
        JsonNode value = message == null ? null : message.get("value");
        if (varpoint == null || value == null || value.isNull()
                || !topic.endsWith("." + varpoint)) {
            rejected++;
            LOG.warning("executor: dropped a malformed decision on " + topic);
            return;
        }
        if (topic.startsWith(Topics.VARIANT_PREFIX)) {
            variants.publish(varpoint, value.asText());
        } else if (value.isNumber()) {
            blackboard.publish(varpoint, value.asDouble());
        } else if (value.isBoolean()) {
            blackboard.publish(varpoint, value.asBoolean()); // a boolean varpoint: true/false, as BT.CPP reads it
        } else {
            rejected++;
            LOG.warning("executor: dropped a blackboard decision that is neither a number nor a boolean on " + topic);
        }
    }

    /** Publishes on the bus through the executor's connection (its node statuses). */
    public void publish(String topic, String body) {
        bus.publish(topic, body);
    }

    /** Publishes and re-announces after a broker restart (the tree being run). */
    public void publishRetained(String topic, String body) {
        bus.publishRetained(topic, topic, body);
    }

    /** Decisions dropped because they were malformed. */
    public long rejectedCount() {
        return rejected;
    }

    @Override
    public void close() {
        bus.close();
    }
}
