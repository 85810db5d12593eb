package org.miron.runtime.requirement;

import org.apache.commons.math3.distribution.BetaDistribution;

/**
 * The exact (Clopper–Pearson) confidence interval of a binomial proportion: {@code x} successes in
 * {@code n} trials, the interval whose coverage is at least the confidence level for every true
 * proportion. Its ends are Beta quantiles (Clopper and Pearson, 1934): lower {@code B(α/2; x,
 * n−x+1)}, 0 when x = 0; upper {@code B(1−α/2; x+1, n−x)}, 1 when x = n. Always within [0, 1].
 */
public final class ClopperPearson {
    public record Interval(double estimate, double lo, double hi) {
    }

    private ClopperPearson() {
    }

    public static Interval of(int x, int n, double confidence) {
        if (n <= 0 || x < 0 || x > n || !(confidence > 0 && confidence < 1)) {
            throw new IllegalArgumentException("no interval for " + x + " of " + n + " at " + confidence);
        }
        double alpha = 1 - confidence;
        double lo = x == 0 ? 0 : new BetaDistribution(null, x, n - x + 1.0).inverseCumulativeProbability(alpha / 2);
        double hi = x == n ? 1 : new BetaDistribution(null, x + 1.0, n - x).inverseCumulativeProbability(1 - alpha / 2);
        return new Interval((double) x / n, lo, hi);
    }
}
