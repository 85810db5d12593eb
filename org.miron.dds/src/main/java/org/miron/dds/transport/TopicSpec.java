package org.miron.dds.transport;

import java.util.List;

/**
 * One DDS topic as the bridge uses it.
 *
 * @param name       the DDS topic name as on the wire ({@code rt/battery_state} for the ROS 2 topic
 *                   {@code battery_state}, see {@link RosNames})
 * @param type       a ROS 2 type ({@code sensor_msgs/BatteryState}) or a RoQME type ({@code RoqmeEstimate})
 * @param qos        reliability, durability, depth
 * @param partitions the DDS partitions (none for ROS 2 topics; RoQME's topics live in theirs)
 * @param keyed      a keyed topic (WITH_KEY: RoQME's types as their original IDL declares them,
 *                   {@code @key name}); DDS never matches a keyed topic with an unkeyed one
 */
public record TopicSpec(String name, String type, Qos qos, List<String> partitions, boolean keyed) {
    public TopicSpec {
        partitions = List.copyOf(partitions);
    }

    /** An unkeyed topic (every ROS 2 topic). */
    public TopicSpec(String name, String type, Qos qos, List<String> partitions) {
        this(name, type, qos, partitions, false);
    }
}
