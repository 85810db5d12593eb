package org.miron.dds.transport;

import com.fasterxml.jackson.databind.node.ObjectNode;

/** The message types a transport carries, by name ({@code sensor_msgs/BatteryState}, {@code RoqmeEstimate}). */
public interface TypeCatalog {
    /** An empty message of the type, every field at its default (what a field path is checked against), or null if unknown. */
    ObjectNode template(String type);
}
