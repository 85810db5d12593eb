package org.miron.dds.transport;

/**
 * ROS 2's conventions on DDS: a topic {@code /a/b} (or {@code a/b}) travels as the DDS topic
 * {@code rt/a/b}, its type {@code pkg/Name} as {@code pkg::msg::dds_::Name_}.
 */
public final class RosNames {
    private RosNames() {
    }

    /** The DDS name of a ROS 2 topic; leading slashes are dropped, as a node in the root namespace does. */
    public static String topic(String rosTopic) {
        String t = rosTopic;
        while (t.startsWith("/")) {
            t = t.substring(1);
        }
        return "rt/" + t;
    }

    /** Whether {@code name} is a valid ROS 2 topic name (letters, digits, underscores, slash-separated tokens). */
    public static boolean validTopic(String name) {
        String t = name.startsWith("/") ? name.substring(1) : name;
        if (t.isEmpty() || t.endsWith("/")) {
            return false;
        }
        for (String token : t.split("/", -1)) {
            if (token.isEmpty() || Character.isDigit(token.charAt(0)) || !token.matches("[A-Za-z0-9_]+") || token.contains("__")) {
                return false;
            }
        }
        return true;
    }
}
