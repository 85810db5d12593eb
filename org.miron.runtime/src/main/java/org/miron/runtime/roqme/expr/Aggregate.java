package org.miron.runtime.roqme.expr;

/**
 * The window functions over {@code size} samples of a ring buffer starting at {@code head}. An empty
 * window has no average, minimum or maximum (unknown); its count and sum are 0. Trends need two
 * samples (a sample window: all n, see Window): {@code increasing} means every sample is greater
 * than the one before.
 */
enum Aggregate {
    AVG, MIN, MAX, SUM, COUNT, INCREASING, DECREASING, STABLE;

    static Aggregate of(String fn) {
        return valueOf(fn.toUpperCase(java.util.Locale.ROOT));
    }

    Object apply(double[] buf, int head, int size) {
        int cap = buf.length;
        switch (this) {
            case COUNT:
                return (double) size;
            case SUM:
            case AVG: {
                if (size == 0) {
                    return this == SUM ? 0.0 : null;
                }
                double sum = 0;
                for (int i = 0; i < size; i++) {
                    sum += buf[(head + i) % cap];
                }
                return this == SUM ? sum : sum / size;
            }
            case MIN:
            case MAX: {
                if (size == 0) {
                    return null;
                }
                double m = buf[head % cap];
                for (int i = 1; i < size; i++) {
                    double v = buf[(head + i) % cap];
                    m = this == MIN ? Math.min(m, v) : Math.max(m, v);
                }
                return m;
            }
            default: {
                if (size < 2) {
                    return null;
                }
                for (int i = 1; i < size; i++) {
                    double prev = buf[(head + i - 1) % cap];
                    double v = buf[(head + i) % cap];
                    boolean ok = switch (this) {
                        case INCREASING -> v > prev;
                        case DECREASING -> v < prev;
                        default -> v == prev;
                    };
                    if (!ok) {
                        return false;
                    }
                }
                return true;
            }
        }
    }
}
