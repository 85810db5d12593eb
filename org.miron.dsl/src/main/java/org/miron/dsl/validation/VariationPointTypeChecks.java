package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;
import static org.miron.dsl.validation.Texts.fmt;
import static org.miron.dsl.validation.Texts.range;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.validation.Check;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.ImpactOnQuality;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.QoSProfiledValue;
import org.miron.dsl.miron.SampleValue;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.BooleanValue;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

/** Types of variation points: one preset per BT enum, samples in range and on the grid, impacts. */
public class VariationPointTypeChecks extends CheckSet {

    private static final MironPackage M = MironPackage.eINSTANCE;
    private static final RoqmePackage R = RoqmePackage.eINSTANCE;
    private static final double GRID_TOLERANCE = 1e-9;

    @Check
    public void checkPreset(BehaviorTreeEnumType type) {
        List<BehaviorTreeLiteral> presets = new ArrayList<>();
        type.getLiterals().stream().filter(l -> l instanceof BehaviorTreeLiteral && ((BehaviorTreeLiteral) l).isPreset())
                .forEach(l -> presets.add((BehaviorTreeLiteral) l));
        String owner = Names.enumName(type);
        if (presets.isEmpty()) {
            error("behavior tree enum of '" + owner + "' needs exactly one 'preset' literal (the nominal behaviour), found none",
                    type, R.getEnumType_Literals(), 0, PRESET_MISSING);
        }
        for (int i = 1; i < presets.size(); i++) {
            error("behavior tree enum of '" + owner + "' needs exactly one 'preset' literal, but '"
                    + presets.get(i).getName() + "' is a second one after '" + presets.get(0).getName() + "'",
                    presets.get(i), M.getBehaviorTreeLiteral_Preset(), PRESET_DUPLICATE);
        }
    }

    @Check
    public void checkSamples(NumericSampledType type) {
        Set<Double> seen = new HashSet<>();
        for (SampleValue sample : type.getSamples()) {
            if (sample.getValue() == null) {
                continue;
            }
            double v = sample.getValue().getValue();
            if ((type.getLower() != null && v < type.getLower()) || (type.getUpper() != null && v > type.getUpper())) {
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is outside the declared range " + range(type),
                        sample, M.getSampleValue_Value(), SAMPLE_OUT_OF_RANGE);
            } else if (type.getPrecision() != null && type.getPrecision() > 0 && !onGrid(v, type)) {
                double base = type.getLower() == null ? 0 : type.getLower();
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is not on the precision grid " + fmt(base)
                        + " + k*" + fmt(type.getPrecision()),
                        sample, M.getSampleValue_Value(), SAMPLE_OFF_GRID);
            } else if (!seen.add(v)) {
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is declared twice", sample,
                        M.getSampleValue_Value(), SAMPLE_DUPLICATE);
            }
        }
    }

    /** Whether v is lower + k * precision for some integer k (lower 0 when unbounded). */
    static boolean onGrid(double v, NumericType type) {
        double base = type.getLower() == null ? 0 : type.getLower();
        double steps = (v - base) / type.getPrecision();
        return Math.abs(steps - Math.rint(steps)) < GRID_TOLERANCE * Math.max(1, Math.abs(steps));
    }

    @Check
    public void checkImpacts(QoSProfiledValue value) {
        Set<EObject> seen = new HashSet<>();
        for (ImpactOnQuality impact : value.getImpacts()) {
            if (impact.getProperty() != null && !impact.getProperty().eIsProxy() && !seen.add(impact.getProperty())) {
                error("impact on '" + impact.getProperty().getName() + "' is declared twice", impact,
                        M.getImpactOnQuality_Property(), IMPACT_DUPLICATE);
            }
        }
    }

    /**
     * {@code := v}: the varpoint's value when the robot starts, so it must be one of its values: a
     * number in its range and on its grid, one of its own enum literals, or a Boolean.
     */
    @Check
    public void checkInitialValue(VariationPoint vp) {
        Expression init = vp.getInitializedTo();
        if (init == null) {
            return;
        }
        DataType type = Types.dataType(vp);
        String problem = null;
        if (type instanceof NumericType n) {
            if (!(init instanceof NumericValue v)) {
                problem = "is not a number";
            } else if ((n.getLower() != null && v.getValue() < n.getLower())
                    || (n.getUpper() != null && v.getValue() > n.getUpper())) {
                problem = "is outside its range " + range(n);
            } else if (n.getPrecision() != null && n.getPrecision() > 0 && !onGrid(v.getValue(), n)) {
                problem = "is not on its precision grid " + fmt(n.getLower() == null ? 0 : n.getLower()) + " + k*"
                        + fmt(n.getPrecision());
            }
        } else if (type instanceof EnumType e) {
            if (!(init instanceof EnumValue v) || v.getLiteral() == null || !e.getLiterals().contains(v.getLiteral())) {
                problem = "is not one of its literals";
            }
        } else if (type instanceof BooleanType) {
            if (!(init instanceof BooleanValue)) {
                problem = "is not true or false";
            }
        } else {
            problem = "cannot be given: only numbers, enums and Booleans have initial values";
        }
        if (problem != null) {
            error("initial value of varpoint '" + vp.getName() + "' " + problem, vp, R.getTypedVariable_InitializedTo(),
                    INITIAL_NOT_A_VALUE);
        }
    }
}
