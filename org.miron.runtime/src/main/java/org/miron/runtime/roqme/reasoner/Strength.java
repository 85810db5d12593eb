package org.miron.runtime.roqme.reasoner;

import java.util.Locale;

/** Likelihood ratios of the demonstrators' reasoner (docs/roqme-provider.md, "Reasoner"). */
public final class Strength {
    private Strength() {
    }

    /** r of {@code reinforces} at a strength (null: MEDIUM); {@code undermines} uses 1/r. */
    public static double ratio(String kind, String strength) {
        String s = strength == null ? "MEDIUM" : strength.toUpperCase(Locale.ROOT);
        double r = switch (s) {
            case "VERYHIGH" -> 0.1;
            case "HIGH" -> 0.3;
            case "MEDIUM" -> 0.5;
            case "LOW" -> 0.7;
            case "VERYLOW" -> 0.9;
            default -> throw new IllegalArgumentException("unknown strength " + strength);
        };
        return "undermines".equals(kind) ? 1 / r : r;
    }
}
