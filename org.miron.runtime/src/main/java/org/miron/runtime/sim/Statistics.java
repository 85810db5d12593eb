package org.miron.runtime.sim;

import java.util.List;

/** Mean and 95 % confidence interval of a measure over independent runs (Student's t). */
public final class Statistics {
    /** t(0.975, df) for df = 1..30; beyond, the normal 1.96 is close enough. */
    private static final double[] T975 = { 12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201,
        2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052,
        2.048, 2.045, 2.042 };

    /** The mean and its interval; with one run the interval is the value itself. */
    public record Summary(double mean, double lo, double hi) {
    }

    private Statistics() {
    }

    public static Summary of(List<Double> values) {
        int n = values.size();
        if (n == 0) {
            return new Summary(Double.NaN, Double.NaN, Double.NaN);
        }
        double sum = 0;
        for (double v : values) {
            sum += v;
        }
        double mean = sum / n;
        if (n == 1) {
            return new Summary(mean, mean, mean);
        }
        double ss = 0;
        for (double v : values) {
            ss += (v - mean) * (v - mean);
        }
        double half = t975(n - 1) * Math.sqrt(ss / (n - 1)) / Math.sqrt(n);
        return new Summary(mean, mean - half, mean + half);
    }

    static double t975(int df) {
        return df <= T975.length ? T975[df - 1] : 1.96;
    }
}
