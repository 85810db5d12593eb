package org.miron.runtime.sim;

import java.util.Arrays;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Mean and 95 % confidence interval of a measure over independent runs: Efron's bootstrap
 * percentile interval (Efron and Tibshirani, An Introduction to the Bootstrap, ch. 13) of the
 * mean, from {@value #RESAMPLES} resamples of the runs drawn with replacement.
 *
 * <p>Why not Student's t, as before: a count, a duration or a share cannot be negative and a
 * metric lies in [0, 1], but a t interval over a few runs is symmetric and left those ranges
 * (near misses over 3 runs: [-6.6, 29.3]). Every resampled mean lies between the smallest and the
 * largest run, so the interval never leaves a measure's range, whatever the range is. With few
 * runs it understates the uncertainty (with 3 runs it is at most the runs' span): run more for a
 * tight answer. The resamples come from a fixed seed: the same runs give the same bytes.
 */
public final class Statistics {
    static final int RESAMPLES = 10_000;
    /** What the interval is, for the footnotes of the table and the report. */
    public static final String INTERVAL = "95 % bootstrap interval (percentile, 10 000 resamples of the runs)";

    /** The mean and its interval; with one run, or runs all equal, the interval is the value itself. */
    public record Summary(double mean, double lo, double hi) {
    }

    private Statistics() {
    }

    public static Summary of(List<Double> values) {
        int n = values.size();
        if (n == 0) {
            return new Summary(Double.NaN, Double.NaN, Double.NaN);
        }
        double[] x = values.stream().mapToDouble(Double::doubleValue).toArray();
        double mean = mean(x);
        if (Arrays.stream(x).allMatch(v -> v == x[0])) {
            return new Summary(mean, mean, mean);
        }
        SplittableRandom random = new SplittableRandom(20261202L);
        double[] means = new double[RESAMPLES];
        for (int b = 0; b < RESAMPLES; b++) {
            double sum = 0;
            for (int i = 0; i < n; i++) {
                sum += x[random.nextInt(n)];
            }
            means[b] = sum / n;
        }
        Arrays.sort(means);
        return new Summary(mean, quantile(means, 0.025), quantile(means, 0.975));
    }

    private static double mean(double[] x) {
        double sum = 0;
        for (double v : x) {
            sum += v;
        }
        return sum / x.length;
    }

    /** The p-quantile of sorted values, interpolated between the two order statistics around it. */
    private static double quantile(double[] sorted, double p) {
        double h = p * (sorted.length - 1);
        int i = (int) Math.floor(h);
        int j = Math.min(i + 1, sorted.length - 1);
        return sorted[i] + (h - i) * (sorted[j] - sorted[i]);
    }
}
