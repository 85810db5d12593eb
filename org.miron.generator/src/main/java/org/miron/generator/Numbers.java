package org.miron.generator;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

/** Number formatting shared by the generators: short, exact-looking and deterministic. */
public final class Numbers {
    private Numbers() {
    }

    /** Rounds away binary noise (0.30000000000000004 → 0.3): 12 significant digits. */
    public static BigDecimal clean(double value) {
        if (value == 0) {
            return BigDecimal.ZERO;
        }
        return new BigDecimal(value).round(new MathContext(12, RoundingMode.HALF_EVEN)).stripTrailingZeros();
    }

    /** JSON style: 10, 0.25, -3 (no exponent). */
    public static String json(BigDecimal value) {
        BigDecimal v = value.signum() == 0 ? BigDecimal.ZERO : value.stripTrailingZeros();
        return v.toPlainString();
    }

    public static String json(double value) {
        return json(clean(value));
    }

    /** MiniZinc float literal: always with a decimal point (10.0, 0.25). */
    public static String mzn(BigDecimal value) {
        String s = json(value);
        return s.contains(".") ? s : s + ".0";
    }

    public static String mzn(double value) {
        return mzn(clean(value));
    }

    /** A utility, to six decimals (enough for the objective's 0.01 resolution). */
    public static String utility(double value) {
        return mzn(BigDecimal.valueOf(value).setScale(6, RoundingMode.HALF_EVEN));
    }
}
