package org.miron.dds.transport;

import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.dds.types.TypeRegistry;

/** The message types a transport carries, by name ({@code sensor_msgs/BatteryState}, {@code RoqmeEstimate}). */
public interface TypeCatalog {
    /** An empty message of the type, every field at its default (what a field path is checked against), or null if unknown. */
    ObjectNode template(String type);

    /** The catalog with the loaded packages' types, which win over the shipped ones of the same name. */
    default TypeCatalog withPackages(TypeRegistry packages) {
        return this;
    }

    /** Whether the type is shipped (a loaded package redefining it is warned about). */
    default boolean ships(String type) {
        return template(type) != null;
    }
}
