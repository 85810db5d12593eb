package org.miron.dds.config;

import java.net.InetAddress;
import java.util.List;
import org.miron.dds.transport.Qos;
import org.miron.dds.types.TypeRegistry;

/**
 * A bridge configuration (docs/dds.md, docs/dds-bridge.schema.json), checked: every type known,
 * every field path present in its type, every name well-formed.
 */
public record BridgeConfig(int domain, String name, List<InetAddress> interfaces, List<ContextMapping> contexts,
        List<DecisionMapping> decisions, List<EstimateMapping> estimates, RoqmeTopics roqme, TypeRegistry types) {

    /** Whether a decision mapping answers change-parameter queries (then the bridge stands in for the skill interface). */
    public boolean answersParameters() {
        return decisions.stream().anyMatch(d -> d.parameter() != null);
    }

    /** The RoQME context type of a value: how {@code roqme.context}'s {@code type} names it. */
    public enum ContextType {
        NUMBER, BOOLEAN, ENUM, EVENT;

        public String json() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /**
     * A ROS 2 topic feeding a RoQME context.
     *
     * @param path  the field, as names into nested messages and indices into sequences
     *              ({@code percentage}, {@code header.stamp.sec}, {@code cell_voltage[0]})
     * @param scale multiplies a number (1 when absent)
     */
    public record ContextMapping(String topic, String type, String field, List<Object> path, double scale, String context,
            String namespace, ContextType as, Qos qos) {
    }

    /**
     * A varpoint's decision published on a ROS 2 topic, into one field of a message of any known type.
     *
     * @param path      the field the decided value goes to ({@code data}, {@code speed_limit})
     * @param leaf      what the field holds: a JSON number (integral for integer fields), boolean or text
     * @param scale     multiplies a number (1 when absent)
     * @param base      the message before the decision: every field at its default, then the mapping's {@code set}
     * @param stamp     the message has a {@code header} whose stamp takes the decision's time
     * @param parameter the arch-bound parameter whose change-parameter queries the bridge answers, or null
     */
    public record DecisionMapping(String varpoint, String topic, String type, Qos qos, String field, List<Object> path,
            com.fasterxml.jackson.databind.JsonNode leaf, double scale, com.fasterxml.jackson.databind.node.ObjectNode base,
            boolean stamp, String parameter) {
    }

    /** A metric's {@code roqme.estimate} published as {@code std_msgs/Float64}. */
    public record EstimateMapping(String metric, String namespace, String topic, Qos qos) {
    }

    /**
     * RoQME's own DDS topics: its context topics into {@code roqme.context}, and {@code RoqmeEstimate}
     * out of {@code roqme.estimate} ("out"), into it ("in") or not at all ("none"); keyed by
     * {@code name} as in the original IDL, or unkeyed for peers that declared the structs without the key.
     */
    public record RoqmeTopics(String partition, String namespace, List<String> contextTopics, String estimates, Qos qos,
            boolean keyed) {
    }
}
