package org.miron.dds.transport;

/**
 * The QoS of one mapping, in ROS 2's terms (rclcpp's profiles): reliability, durability and a
 * keep-last history depth.
 */
public record Qos(boolean reliable, boolean transientLocal, int depth) {
    /** ROS 2's default profile: reliable, volatile, keep last 10. */
    public static final Qos DEFAULT = new Qos(true, false, 10);
    /** What a latched ROS 2 topic (Nav2's selectors) expects: reliable, transient-local, keep last 1. */
    public static final Qos LATCHED = new Qos(true, true, 1);

    public Qos {
        if (depth < 1) {
            throw new IllegalArgumentException("the history depth must be at least 1, got " + depth);
        }
    }

    @Override
    public String toString() {
        return (reliable ? "reliable" : "best-effort") + ", " + (transientLocal ? "transient-local" : "volatile") + ", depth " + depth;
    }
}
