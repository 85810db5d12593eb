package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;

/**
 * A variation point from {@code name.io.json}; decisions are 0-based indices into {@code values}.
 *
 * @param kind    {@code enum} or {@code number}
 * @param values  literal names (enum) or numbers, as JSON so numbers are never truncated
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

    public String bindingType() {
        return binding == null ? "none" : binding.type();
    }
}
