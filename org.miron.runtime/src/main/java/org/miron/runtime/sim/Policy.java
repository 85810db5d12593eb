package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.util.LinkedHashMap;
import java.util.Map;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.VariationPoint;

/**
 * How a simulated robot chooses its variation points: {@code adaptive} (the MIRoN model's engine),
 * {@code preset} (every varpoint at its preset, nothing adapts) or {@code fixed:vp=value,...} (those
 * values, the other varpoints at their presets).
 */
public record Policy(String name, boolean adaptive, Map<String, String> fixed) {

    /** Parses {@code adaptive}, {@code preset} or {@code fixed:vp=value,...}; IllegalArgumentException says what is wrong. */
    public static Policy parse(String text) {
        if (text.equals("adaptive")) {
            return new Policy(text, true, Map.of());
        }
        if (text.equals("preset")) {
            return new Policy(text, false, Map.of());
        }
        if (text.startsWith("fixed:")) {
            Map<String, String> values = new LinkedHashMap<>();
            for (String part : text.substring("fixed:".length()).split(",")) {
                int eq = part.indexOf('=');
                if (eq <= 0 || eq == part.length() - 1) {
                    throw new IllegalArgumentException("policy '" + text + "': write fixed:varpoint=value,... (got '" + part + "')");
                }
                values.put(part.substring(0, eq).trim(), part.substring(eq + 1).trim());
            }
            return new Policy(text, false, values);
        }
        throw new IllegalArgumentException("unknown policy '" + text + "' (adaptive, preset or fixed:varpoint=value,...)");
    }

    /**
     * The value index of every varpoint this non-adaptive policy sets (its fixed value, else its
     * preset, else the value the robot starts with); varpoints with none are left alone.
     */
    public Map<VariationPoint, Integer> configuration(IoModel model) {
        Map<VariationPoint, Integer> out = new LinkedHashMap<>();
        for (String vp : fixed.keySet()) {
            if (model.varpoint(vp).isEmpty()) {
                throw new IllegalArgumentException("policy '" + name + "': no varpoint '" + vp + "' in " + model.model()
                        + " (varpoints: " + model.varpoints().stream().map(VariationPoint::name).toList() + ")");
            }
        }
        for (VariationPoint vp : model.varpoints()) {
            String given = fixed.get(vp.name());
            if (given != null) {
                int index = vp.indexOf(json(given));
                if (index < 0) {
                    throw new IllegalArgumentException("policy '" + name + "': " + given + " is not a value of " + vp.name()
                            + " (" + (vp.values().size() > 12 ? vp.values().get(0) + " .. " + vp.values().get(vp.values().size() - 1)
                                    : vp.values()) + ")");
                }
                out.put(vp, index);
            } else if (vp.preset() != null) {
                out.put(vp, vp.preset());
            } else if (vp.initial() != null) {
                out.put(vp, vp.initial());
            }
        }
        return out;
    }

    private static JsonNode json(String text) {
        if (text.equals("true") || text.equals("false")) {
            return BooleanNode.valueOf(Boolean.parseBoolean(text));
        }
        try {
            return DoubleNode.valueOf(Double.parseDouble(text));
        } catch (NumberFormatException e) {
            return TextNode.valueOf(text);
        }
    }
}
