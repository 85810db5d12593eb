package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * One field of a message definition.
 *
 * @param defaultValue the definition's default ({@code uint8 x 5}), or null for ROS 2's zero value
 * @param line         where the field's type stands in its file, for errors about it
 */
public record MsgField(String name, FieldType type, JsonNode defaultValue, int line, int column) {
}
