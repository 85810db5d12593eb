package org.miron.runtime.player;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

/**
 * A timed scenario: a JSON array of steps, each with {@code at} (ms from the start) and exactly
 * one of {@code estimate} or {@code context}, whose object is the RoQME message body:
 * <pre>
 * [ {"at": 0,    "context":  {"name": "BatteryLevel", "namespace": "Intralogistics", "type": "number", "value": 80}},
 *   {"at": 2000, "estimate": {"name": "power_autonomy", "namespace": "Intralogistics", "value": 0.2}} ]
 * </pre>
 * A missing {@code time} is filled in with the wall clock when the step is played. Steps are
 * played in {@code at} order.
 */
public record Scenario(List<Step> steps) {

    /** @param topic {@code roqme.estimate} or {@code roqme.context} */
    public record Step(long at, String topic, ObjectNode body) {
    }

    public static Scenario load(Path file) throws IOException {
        JsonNode root = Json.MAPPER.readTree(file.toFile());
        try {
            return parse(root);
        } catch (IllegalArgumentException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
    }

    public static Scenario parse(JsonNode root) {
        if (root == null || !root.isArray()) {
            throw new IllegalArgumentException("a scenario is a JSON array of {\"at\": ms, \"estimate\"|\"context\": {...}}");
        }
        List<Step> steps = new ArrayList<>();
        int i = 0;
        for (JsonNode s : root) {
            if (!s.path("at").isNumber() || s.get("at").asLong() < 0) {
                throw new IllegalArgumentException("step " + i + ": 'at' must be a number of ms >= 0");
            }
            boolean est = s.path("estimate").isObject();
            boolean ctx = s.path("context").isObject();
            if (est == ctx) {
                throw new IllegalArgumentException("step " + i + ": needs exactly one of 'estimate' or 'context' (an object)");
            }
            ObjectNode body = (ObjectNode) (est ? s.get("estimate") : s.get("context"));
            steps.add(new Step(s.get("at").asLong(), est ? Topics.ESTIMATE : Topics.CONTEXT, body));
            i++;
        }
        steps.sort(Comparator.comparingLong(Step::at)); // stable: equal times keep file order
        return new Scenario(List.copyOf(steps));
    }
}
