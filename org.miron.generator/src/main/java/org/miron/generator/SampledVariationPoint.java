package org.miron.generator;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.Property;

/**
 * A variation point reduced to what the MiniZinc model needs: its value table (the decision
 * &lt;vp&gt;_var is a 0-based index into it) and one utility table per property its impacts name.
 */
public final class SampledVariationPoint {
    public enum Kind {
        /** Enum literals (labels); the value of index i is i. */
        ENUM,
        /** Sampled numbers (booleans are the numbers 0 and 1, see {@link #bool}). */
        NUMBER
    }

    public final VariationPoint varpoint;
    public final String name;
    public final Kind kind;
    /** Enum: the literals in declaration order (preset included); empty for numbers. */
    public final List<EnumLiteral> literals = new ArrayList<>();
    /** Number: the sampled values; for an enum 0..k-1. */
    public final List<BigDecimal> values = new ArrayList<>();
    /** Distance between neighbouring values (numbers), used for "=" within half a step. */
    public BigDecimal step;
    /**
     * A boolean varpoint: MiniZinc sees the numbers 0 and 1, io.json and everything after it the
     * values {@code false} and {@code true}.
     */
    public boolean bool;
    /** Index of the preset literal, -1 when there is none. */
    public int preset = -1;
    /** Utility in [0,100] of each value, per property, in order of first mention. */
    public final Map<Property, double[]> utilities = new LinkedHashMap<>();

    public SampledVariationPoint(VariationPoint varpoint, Kind kind) {
        this.varpoint = varpoint;
        this.name = varpoint.getName();
        this.kind = kind;
    }

    public boolean isEnum() {
        return kind == Kind.ENUM;
    }

    public int size() {
        return isEnum() ? literals.size() : values.size();
    }

    /**
     * Index of the initial value ({@code := v}, validated to be one of the values; a number is
     * taken at its nearest sampled value), -1 when none is given.
     */
    public int initial() {
        org.miron.dsl.roqme.Expression init = varpoint.getInitializedTo();
        if (init instanceof org.miron.dsl.roqme.EnumValue e) {
            return literals.indexOf(e.getLiteral());
        }
        double x;
        if (init instanceof org.miron.dsl.roqme.NumericValue n) {
            x = n.getValue();
        } else if (init instanceof org.miron.dsl.roqme.BooleanValue b) {
            x = b.isValue() ? 1 : 0;
        } else {
            return -1;
        }
        int best = -1;
        for (int i = 0; i < values.size(); i++) {
            if (best < 0 || Math.abs(values.get(i).doubleValue() - x) < Math.abs(values.get(best).doubleValue() - x)) {
                best = i;
            }
        }
        return best;
    }

    public List<String> labels() {
        List<String> labels = new ArrayList<>();
        literals.forEach(l -> labels.add(l.getName()));
        return labels;
    }

    // MiniZinc names of this varpoint (docs/generators.md).
    public String n() { return name + "_n"; }
    public String x() { return name + "_x"; }
    public String lbl() { return name + "_lbl"; }
    public String decision() { return name + "_var"; }
    public String input() { return name + "_input"; }
    public String inputValue() { return name + "_input_value"; }
    public String current() { return name + "_current"; }
    public String presetParam() { return name + "_preset"; }
    public String gain() { return name + "_gain"; }
    public String selection() { return name + "_sel"; }
}
