package org.miron.dds;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.dds.config.BridgeConfig.ContextMapping;
import org.miron.dds.config.BridgeConfig.ContextType;
import org.miron.dds.config.FieldPath;
import org.miron.runtime.bus.ContextMessage;

/**
 * DDS samples to {@code roqme.context} bodies ({@code {"name","namespace","type","value","time"}},
 * docs/wire-formats.md): a ROS 2 message through its mapping's field path and scale, or one of
 * RoQME's own context structs ({@code name} and a sequence of values, the first one used).
 */
final class ContextConversion {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    private ContextConversion() {
    }

    static ObjectNode fromRos(ContextMapping m, JsonNode message, long time) throws Rejected {
        JsonNode leaf = FieldPath.resolve(message, m.path());
        if (leaf == null) {
            throw new Rejected("no field " + m.field());
        }
        JsonNode value = switch (m.as()) {
            case NUMBER -> F.numberNode(number(m.field(), leaf) * m.scale());
            case BOOLEAN -> {
                if (!leaf.isBoolean()) {
                    throw new Rejected(m.field() + " is " + leaf + ", not a boolean");
                }
                yield leaf;
            }
            case ENUM -> {
                if (!leaf.isTextual() || !leaf.asText().matches("[A-Za-z_][A-Za-z0-9_]*")) {
                    throw new Rejected(m.field() + " is " + leaf + ", not an enum literal");
                }
                yield leaf;
            }
            case EVENT -> F.booleanNode(true);
        };
        return body(m.context(), m.namespace(), m.as(), value, time);
    }

    private static double number(String field, JsonNode leaf) throws Rejected {
        double v;
        if (leaf.isNumber()) {
            v = leaf.asDouble();
        } else if (leaf.isTextual()) {
            try {
                v = Double.parseDouble(leaf.asText().trim());
            } catch (NumberFormatException e) {
                throw new Rejected(field + " is " + leaf + ", not a number");
            }
        } else {
            throw new Rejected(field + " is " + leaf + ", not a number");
        }
        if (!Double.isFinite(v)) {
            throw new Rejected(field + " is " + v + ", not a finite number");
        }
        return v;
    }

    /** A RoQME context struct ({@code RoqmeDoubleContext} ...) as a context of the given type. */
    static ObjectNode fromRoqme(String struct, String namespace, JsonNode message, long time) throws Rejected {
        String name = message.path("name").asText("");
        if (!name.matches("[A-Za-z_][A-Za-z0-9_]*")) {
            throw new Rejected("context name \"" + name + "\" is not an identifier");
        }
        JsonNode values = message.path("value");
        if (values.size() == 0) {
            throw new Rejected(name + " has no value");
        }
        JsonNode v = values.get(0);
        return switch (struct) {
            case "RoqmeIntContext", "RoqmeUIntContext", "RoqmeDoubleContext" -> {
                if (!Double.isFinite(v.asDouble())) {
                    throw new Rejected(name + " is " + v + ", not a finite number");
                }
                yield body(name, namespace, ContextType.NUMBER, v, time);
            }
            case "RoqmeBoolContext" -> body(name, namespace, ContextType.BOOLEAN, v, time);
            case "RoqmeEnumContext" -> {
                if (!v.asText().matches("[A-Za-z_][A-Za-z0-9_]*")) {
                    throw new Rejected(name + " is " + v + ", not an enum literal");
                }
                yield body(name, namespace, ContextType.ENUM, v, time);
            }
            default -> body(name, namespace, ContextType.EVENT, F.booleanNode(true), time);
        };
    }

    static ObjectNode body(String name, String namespace, ContextType type, JsonNode value, long time) {
        return ContextMessage.body(name, namespace, type.json(), value, time);
    }
}
