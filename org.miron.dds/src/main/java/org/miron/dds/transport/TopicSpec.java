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
 */
public record TopicSpec(String name, String type, Qos qos, List<String> partitions) {
    public TopicSpec {
        partitions = List.copyOf(partitions);
    }
}
