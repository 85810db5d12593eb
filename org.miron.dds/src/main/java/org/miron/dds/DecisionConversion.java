package org.miron.dds;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.dds.config.BridgeConfig.DecisionMapping;
import org.miron.dds.config.FieldPath;

/**
 * A decided value into a message: the mapping's base message (defaults, then its {@code set}),
 * the value in its field (a number times the scale, rounded for an integer field; a boolean; text
 * for a string field, an enum literal as it is), the header's stamp the decision's time.
 */
final class DecisionConversion {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    private DecisionConversion() {
    }

    /** What goes into the field, or null when the field cannot carry the decided value. */
    static JsonNode value(DecisionMapping d, JsonNode v) {
        JsonNode leaf = d.leaf();
        if (leaf.isTextual()) {
            return F.textNode(v.isNumber() && d.scale() != 1 ? Double.toString(v.asDouble() * d.scale()) : v.asText());
        }
        if (leaf.isBoolean()) {
            return v.isBoolean() ? v : null;
        }
        if (!v.isNumber()) {
            return null;
        }
        double x = v.asDouble() * d.scale();
        if (!Double.isFinite(x)) {
            return null;
        }
        return leaf.isIntegralNumber() ? F.numberNode(Math.round(x)) : F.numberNode(x);
    }

    static ObjectNode message(DecisionMapping d, JsonNode data, long timeMs) {
        ObjectNode m = FieldPath.with(d.base(), d.path(), data);
        if (d.stamp()) {
            ObjectNode stamp = (ObjectNode) m.path("header").path("stamp");
            stamp.put("sec", Math.floorDiv(timeMs, 1000));
            stamp.put("nanosec", Math.floorMod(timeMs, 1000) * 1_000_000L);
        }
        return m;
    }
}
