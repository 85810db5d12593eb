package org.miron.generator;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.ImpactIntensity;
import org.miron.dsl.miron.ImpactOnQuality;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.QoSProfiledValue;
import org.miron.dsl.miron.SampleValue;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.util.Types;

/**
 * Turns a variation point into value and utility tables (docs/generators.md, "The MiniZinc
 * model"): numbers (lo:prec:hi) become lo, lo+prec, ..., hi (200 steps without a precision), enums
 * the indexes 0..k-1; each impact intensity becomes a utility in [0,100], interpolated linearly
 * between numeric samples and back to neutral (50) at the ends of the range.
 */
public class DataSampler {
    /** Steps of a numeric range declared without a precision. */
    public static final int DEFAULT_STEPS = 200;
    /** Beyond this the solver's tables get large and slow: ask for a coarser precision instead. */
    public static final int MAX_VALUES = 20000;
    public static final double NEUTRAL = 50.0;

    private final List<GenerationError> errors;

    public DataSampler(List<GenerationError> errors) {
        this.errors = errors;
    }

    /** ---=0, --=100/6, -=200/6, neutral=50, +=400/6, ++=500/6, +++=100. */
    public static double utility(ImpactIntensity intensity) {
        if (intensity == null) {
            return NEUTRAL;
        }
        return switch (intensity) {
            case VERY_NEGATIVE -> 0.0;
            case NEGATIVE -> 100.0 / 6;
            case SLIGHTLY_NEGATIVE -> 200.0 / 6;
            case SLIGHTLY_POSITIVE -> 400.0 / 6;
            case POSITIVE -> 500.0 / 6;
            case VERY_POSITIVE -> 100.0;
            default -> NEUTRAL;
        };
    }

    /** The tables of a varpoint, or null (after reporting why) when it cannot be sampled. */
    public SampledVariationPoint sample(VariationPoint vp) {
        DataType type = Types.dataType((EObject) vp);
        if (type instanceof EnumType e) {
            return sampleEnum(vp, e);
        } else if (type instanceof NumericType n) {
            return sampleNumber(vp, n);
        } else if (type instanceof BooleanType) {
            return sampleBoolean(vp);
        }
        errors.add(new GenerationError(vp, "varpoint '" + vp.getName()
                + "' cannot be generated: only enum, number and boolean varpoints have a value table"));
        return null;
    }

    private SampledVariationPoint sampleEnum(VariationPoint vp, EnumType type) {
        SampledVariationPoint s = new SampledVariationPoint(vp, SampledVariationPoint.Kind.ENUM);
        s.step = BigDecimal.ONE;
        List<EnumLiteral> literals = type.getLiterals();
        for (int i = 0; i < literals.size(); i++) {
            EnumLiteral literal = literals.get(i);
            s.literals.add(literal);
            s.values.add(BigDecimal.valueOf(i));
            if (literal instanceof BehaviorTreeLiteral bt && bt.isPreset()) {
                s.preset = i;
            }
        }
        for (int i = 0; i < literals.size(); i++) {
            if (literals.get(i) instanceof QoSProfiledValue profiled) {
                for (ImpactOnQuality impact : profiled.getImpacts()) {
                    if (impact.getProperty() != null) {
                        table(s, impact.getProperty())[i] = utility(impact.getIntensity());
                    }
                }
            }
        }
        return s;
    }

    private SampledVariationPoint sampleBoolean(VariationPoint vp) {
        SampledVariationPoint s = new SampledVariationPoint(vp, SampledVariationPoint.Kind.NUMBER);
        s.step = BigDecimal.ONE;
        s.bool = true;
        s.values.add(BigDecimal.ZERO);
        s.values.add(BigDecimal.ONE);
        return s;
    }

    private SampledVariationPoint sampleNumber(VariationPoint vp, NumericType type) {
        List<SampleValue> samples = type instanceof NumericSampledType sampled
                ? sampled.getSamples().stream().filter(v -> v.getValue() != null)
                        .sorted(Comparator.comparingDouble(v -> v.getValue().getValue())).toList()
                : List.of();
        Double lo = type.getLower() != null ? type.getLower() : samples.isEmpty() ? null : valueOf(samples.get(0));
        Double hi = type.getUpper() != null ? type.getUpper()
                : samples.isEmpty() ? null : valueOf(samples.get(samples.size() - 1));
        if (lo == null || hi == null) {
            errors.add(new GenerationError(vp, "numeric varpoint '" + vp.getName()
                    + "' needs a range (lo:hi) or samples to know which values it may take"));
            return null;
        }
        if (hi < lo) {
            errors.add(new GenerationError(vp, "numeric varpoint '" + vp.getName() + "' has an empty range: "
                    + Numbers.json(lo) + " > " + Numbers.json(hi)));
            return null;
        }
        BigDecimal low = Numbers.clean(lo);
        BigDecimal high = Numbers.clean(hi);
        BigDecimal defaultStep = high.subtract(low).divide(BigDecimal.valueOf(DEFAULT_STEPS), MathContext.DECIMAL64);
        BigDecimal step;
        if (type.getPrecision() != null && type.getPrecision() > 0) {
            step = Numbers.clean(type.getPrecision());
        } else if (high.compareTo(low) == 0) {
            step = BigDecimal.ONE;
        } else {
            step = defaultStep.stripTrailingZeros();
        }
        long count = high.subtract(low).divide(step, 0, RoundingMode.FLOOR).longValue() + 1;
        if (count > MAX_VALUES) {
            errors.add(new GenerationError(vp, "numeric varpoint '" + vp.getName() + "' would take " + count
                    + " values (more than " + MAX_VALUES + "): declare a coarser precision, e.g. ("
                    + Numbers.json(low) + ":" + Numbers.json(defaultStep) + ":" + Numbers.json(high) + ")"));
            return null;
        }
        SampledVariationPoint s = new SampledVariationPoint(vp, SampledVariationPoint.Kind.NUMBER);
        s.step = step;
        for (int i = 0; i < (int) count; i++) {
            s.values.add(low.add(step.multiply(BigDecimal.valueOf(i))).stripTrailingZeros());
        }
        Set<Property> properties = new LinkedHashSet<>();
        for (SampleValue sample : samples) {
            for (ImpactOnQuality impact : sample.getImpacts()) {
                if (impact.getProperty() != null) {
                    properties.add(impact.getProperty());
                }
            }
        }
        for (Property p : properties) {
            // Anchors: each sample's utility at its value, neutral at the range ends beyond them.
            List<Double> xs = new ArrayList<>();
            List<Double> ys = new ArrayList<>();
            if (valueOf(samples.get(0)) > lo) {
                xs.add(lo);
                ys.add(NEUTRAL);
            }
            for (SampleValue sample : samples) {
                xs.add(valueOf(sample));
                ys.add(utilityOf(sample, p));
            }
            if (valueOf(samples.get(samples.size() - 1)) < hi) {
                xs.add(hi);
                ys.add(NEUTRAL);
            }
            double[] table = table(s, p);
            for (int i = 0; i < s.size(); i++) {
                table[i] = interpolate(xs, ys, s.values.get(i).doubleValue());
            }
        }
        return s;
    }

    private static double valueOf(SampleValue sample) {
        return sample.getValue().getValue();
    }

    private static double utilityOf(SampleValue sample, Property p) {
        return sample.getImpacts().stream().filter(impact -> impact.getProperty() == p).findFirst()
                .map(impact -> utility(impact.getIntensity())).orElse(NEUTRAL);
    }

    /** Piecewise-linear through (xs, ys), xs ascending; constant outside. */
    public static double interpolate(List<Double> xs, List<Double> ys, double x) {
        if (x <= xs.get(0)) {
            return ys.get(0);
        }
        for (int i = 1; i < xs.size(); i++) {
            if (x <= xs.get(i)) {
                double x0 = xs.get(i - 1);
                double x1 = xs.get(i);
                return ys.get(i - 1) + (ys.get(i) - ys.get(i - 1)) * (x - x0) / (x1 - x0);
            }
        }
        return ys.get(ys.size() - 1);
    }

    private static double[] table(SampledVariationPoint s, Property p) {
        return s.utilities.computeIfAbsent(p, key -> {
            double[] table = new double[s.size()];
            Arrays.fill(table, NEUTRAL);
            return table;
        });
    }
}
