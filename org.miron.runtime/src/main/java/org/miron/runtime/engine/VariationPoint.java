package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.util.List;

/**
 * A variation point from {@code name.io.json}; decisions are 0-based indices into {@code values}.
 *
 * @param kind    {@code enum}, {@code number} or {@code boolean}
 * @param values  literal names (enum), numbers (as JSON so they are never truncated) or
 *                {@code [false, true]} (boolean: the .mzn's 0 and 1, by index)
 * @param preset  index of the design-time choice, or null
 * @param binding how a decision is applied, null for decision-only varpoints
 * @param initial index of the value the robot starts with ({@code := v}), or null: it is the applied
 *                value before any decision, and nothing is sent for it until a rule or impact asks
 */
public record VariationPoint(String name, String kind, List<JsonNode> values, Integer preset, String decision,
        String input, String inputValue, String current, Binding binding, Integer initial) {

    /** Index of a value given from outside (override), or -1 when it is not one of {@code values}. */
    public int indexOf(JsonNode value) {
        for (int i = 0; i < values.size(); i++) {
            JsonNode v = values.get(i);
            if (v.isNumber() && value.isNumber() ? v.asDouble() == value.asDouble() : v.equals(value)) {
                return i;
            }
        }
        return -1;
    }

    /** The value at a decision index, JSON null when there is none (a {@code current} of -1). */
    public JsonNode valueAt(int index) {
        return index >= 0 && index < values.size() ? values.get(index) : NullNode.getInstance();
    }

    public boolean isBoolean() {
        return kind.equals("boolean");
    }

    public String bindingType() {
        return binding == null ? "none" : binding.type();
    }
}
