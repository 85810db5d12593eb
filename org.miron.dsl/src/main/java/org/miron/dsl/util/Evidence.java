package org.miron.dsl.util;

import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.EvidenceAction;
import org.miron.dsl.roqme.Strength;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.Undermines;

/**
 * The numbers of the RoQME reasoner that a model's text implies (the RoQME runtime spec of issue 22, "The
 * reasoner"): likelihood ratios of the action strengths, the default reference and survival, and
 * times in milliseconds. One place, so that the editor's hovers, the generator and anything else
 * that explains a model say the same as the provider computes.
 */
public final class Evidence {

    /** A belief's reference when the model gives none. */
    public static final double DEFAULT_REFERENCE = 0.5;
    /** Survival of evidence when neither the action nor its belief gives one: 5 minutes. */
    public static final long DEFAULT_SURVIVAL_MS = 5 * 60_000L;

    private Evidence() {
    }

    /** The strength an action states; an omitted strength is MEDIUM. */
    public static Strength strength(Strength written) {
        return written == null || written == Strength.UNSPECIFIED ? Strength.MEDIUM : written;
    }

    /** The likelihood ratio of `reinforces` with this strength: below 1, the smaller the stronger. */
    public static double reinforcingRatio(Strength written) {
        switch (strength(written)) {
        case VERYHIGH:
            return 0.1;
        case HIGH:
            return 0.3;
        case LOW:
            return 0.7;
        case VERYLOW:
            return 0.9;
        default:
            return 0.5;
        }
    }

    /** The likelihood ratio of an evidence action: `undermines` uses the inverse of `reinforces`. */
    public static double ratio(EvidenceAction action) {
        double r = reinforcingRatio(action.getStrength());
        return action instanceof Undermines ? 1 / r : r;
    }

    /** The action's survival, else its belief's, else {@link #DEFAULT_SURVIVAL_MS}. */
    public static long survivalMs(EvidenceAction action) {
        if (action.getSurvival() != null) {
            return millis(action.getSurvival());
        }
        BeliefVariable belief = action.getBelief();
        return belief != null && !belief.eIsProxy() && belief.getSurvival() != null ? millis(belief.getSurvival())
                : DEFAULT_SURVIVAL_MS;
    }

    /** A belief's reference, {@link #DEFAULT_REFERENCE} when omitted. */
    public static double reference(BeliefVariable belief) {
        return belief.getReference() == null ? DEFAULT_REFERENCE : belief.getReference();
    }

    /** A time literal in milliseconds (rounded to the nearest one). */
    public static long millis(TimeValue time) {
        return Math.round(time.getValue() * unitMs(time));
    }

    /** A time literal in milliseconds, unrounded (1.5 milliseconds stays 1.5). */
    public static double exactMillis(TimeValue time) {
        return time.getValue() * unitMs(time);
    }

    private static double unitMs(TimeValue time) {
        switch (time.getUnit()) {
        case SECONDS:
            return 1_000;
        case MINUTES:
            return 60_000;
        case HOURS:
            return 3_600_000;
        case DAYS:
            return 86_400_000;
        default:
            return 1;
        }
    }

    /** A time in milliseconds as people read it: "5 minutes", "90 seconds", "250 ms". */
    public static String describe(double ms) {
        if (ms >= 86_400_000 && ms % 86_400_000 == 0) {
            return plural(ms / 86_400_000, "day");
        } else if (ms >= 3_600_000 && ms % 3_600_000 == 0) {
            return plural(ms / 3_600_000, "hour");
        } else if (ms >= 60_000 && ms % 60_000 == 0) {
            return plural(ms / 60_000, "minute");
        } else if (ms >= 1_000 && ms % 1_000 == 0) {
            return plural(ms / 1_000, "second");
        }
        return number(ms) + " ms";
    }

    private static String plural(double n, String unit) {
        return number(n) + " " + unit + (n == 1 ? "" : "s");
    }

    /** A ratio or time for people: 0.5, 2, 3.333 (at most three decimals). */
    public static String number(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        String text = String.format(java.util.Locale.ROOT, "%.3f", value);
        return text.replaceAll("0+$", "").replaceAll("\\.$", "");
    }
}
