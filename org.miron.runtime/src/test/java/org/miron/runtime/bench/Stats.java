package org.miron.runtime.bench;

import java.util.Arrays;

/** Percentiles of a sample of durations in nanoseconds, printed in milliseconds. */
final class Stats {
    private final long[] nanos;

    Stats(long[] nanos) {
        this.nanos = nanos.clone();
        Arrays.sort(this.nanos);
    }

    double percentileMs(double p) {
        if (nanos.length == 0) {
            return Double.NaN;
        }
        int i = (int) Math.ceil(p / 100.0 * nanos.length) - 1;
        return nanos[Math.max(0, Math.min(nanos.length - 1, i))] / 1e6;
    }

    String p50p99() {
        return String.format("%9.3f %9.3f", percentileMs(50), percentileMs(99)); // µs: the native backend's scale
    }
}
