package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Map;

/**
 * A message definition read from a .msg or .idl file: its fields in wire order and its constants
 * (parsed, never serialised: ROS 2 puts them in the generated code, not on the wire).
 *
 * @param file where it was defined (a file name, or "shipped:" for the bridge's own copies)
 */
public record MsgType(String pkg, String name, List<MsgField> fields, Map<String, JsonNode> constants, String file) {
    public MsgType {
        fields = List.copyOf(fields);
        constants = Map.copyOf(constants);
    }

    /** {@code pkg/Name}, as configurations and .msg files name it. */
    public String fullName() {
        return pkg + "/" + name;
    }

    /** The DDS type name ROS 2 gives it: {@code pkg::msg::dds_::Name_}. */
    public String ddsName() {
        return pkg + "::msg::dds_::" + name + "_";
    }

    public MsgField field(String fieldName) {
        for (MsgField f : fields) {
            if (f.name().equals(fieldName)) {
                return f;
            }
        }
        return null;
    }
}
