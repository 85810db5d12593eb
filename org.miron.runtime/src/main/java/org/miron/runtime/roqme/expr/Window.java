package org.miron.runtime.roqme.expr;

/**
 * A sliding window over the samples of one source (a variable, an expression or an event), as a
 * computed slot: a window of the last {@code n} samples, or of the samples of the last {@code ms}
 * milliseconds (a sample of time t is in the window at time now while t > now - ms). Memory is
 * bounded by the window: a sample window holds n samples, a time window only what arrived in its
 * last ms (the ring grows to the largest such count and is reused). {@code period(x)} is a
 * two-sample window of update times.
 */
public final class Window {
    final int slot;
    final int index;
    private final ValueNode source; // null for an event source: each occurrence is a sample 1
    private final EventNode event;
    private final int[] sourceDeps;
    private final Aggregate fn; // null for period
    private final int maxSamples; // >0: sample window
    private final long ms; // >0: time window
    private double[] values;
    private long[] times;
    private int head;
    private int size;
    // Kept up to date on every push and drop, so a sample costs O(1) except for min and max:
    private double sum; // of the samples in the window (recomputed exactly now and then: no drift)
    private int breaks; // adjacent pairs that break the trend (increasing, decreasing, stable)
    private int drops;

    Window(int index, int slot, ValueNode source, EventNode event, int[] sourceDeps, Aggregate fn, int maxSamples, long ms) {
        this.index = index;
        this.slot = slot;
        this.source = source;
        this.event = event;
        this.sourceDeps = sourceDeps;
        this.fn = fn;
        this.maxSamples = maxSamples;
        this.ms = ms;
        int cap = maxSamples > 0 ? maxSamples : 16;
        values = new double[cap];
        times = new long[cap];
    }

    public int slot() {
        return slot;
    }

    /** Position in the model's list of windows. */
    public int index() {
        return index;
    }

    public int[] deps() {
        return sourceDeps;
    }

    /** Time of the oldest sample plus the window's length (when it must drop it), or -1. */
    public long nextExpiry() {
        return ms > 0 && size > 0 ? times[head] + ms : -1;
    }

    /** Samples the source in a step where it was updated; true when the window's value changed slot. */
    public void sample(Store s) {
        double v;
        if (event != null) {
            if (!event.occurs(s)) {
                return;
            }
            v = 1;
        } else {
            Object o = source.eval(s);
            if (o instanceof Double d) {
                v = d;
            } else if (o instanceof Boolean b) {
                v = b ? 1 : 0;
            } else if (o != null && (fn == Aggregate.COUNT || fn == null)) {
                v = 1;
            } else {
                return; // unknown (or not a number): no sample
            }
        }
        trim(s.now());
        if (maxSamples > 0 && size == maxSamples) {
            dropHead();
        } else if (size == values.length) {
            grow();
        }
        double x = fn == null ? s.now() : v;
        if (size > 0 && !keepsTrend(values[(head + size - 1) % values.length], x)) {
            breaks++;
        }
        int i = (head + size) % values.length;
        values[i] = x;
        times[i] = s.now();
        size++;
        sum += x;
        s.set(slot, value());
    }

    /** Sets the slot to the empty window's value (count and sum 0, the others unknown). */
    public void init(Store s) {
        s.values[slot] = value();
    }

    /** Drops samples that left a time window at {@code now}; updates the slot when any did. */
    public boolean expire(Store s) {
        if (trim(s.now())) {
            s.set(slot, value());
            return true;
        }
        return false;
    }

    private boolean trim(long now) {
        boolean dropped = false;
        while (ms > 0 && size > 0 && times[head] <= now - ms) {
            dropHead();
            dropped = true;
        }
        return dropped;
    }

    private void dropHead() {
        double x = values[head];
        if (size > 1 && !keepsTrend(x, values[(head + 1) % values.length])) {
            breaks--;
        }
        head = (head + 1) % values.length;
        size--;
        sum -= x;
        if (size == 0) {
            sum = 0;
        } else if (++drops % 1024 == 0) {
            sum = 0;
            for (int i = 0; i < size; i++) {
                sum += values[(head + i) % values.length];
            }
        }
    }

    private boolean keepsTrend(double prev, double v) {
        if (fn == null) {
            return true;
        }
        return switch (fn) {
            case INCREASING -> v > prev;
            case DECREASING -> v < prev;
            case STABLE -> v == prev;
            default -> true;
        };
    }

    private Object value() {
        if (fn == null) { // period: time between the last two updates
            return size < 2 ? null : values[(head + size - 1) % values.length] - values[(head + size - 2) % values.length];
        }
        return switch (fn) {
            case COUNT -> (double) size;
            case SUM -> size == 0 ? 0.0 : sum;
            case AVG -> size == 0 ? null : (Object) (sum / size);
            // a trend over the last n samples needs n of them; over a time window, two
            case INCREASING, DECREASING, STABLE -> size < Math.max(2, maxSamples) ? null : (Object) (breaks == 0);
            default -> fn.apply(values, head, size); // min, max
        };
    }

    private void grow() {
        double[] v = new double[values.length * 2];
        long[] t = new long[values.length * 2];
        for (int i = 0; i < size; i++) {
            v[i] = values[(head + i) % values.length];
            t[i] = times[(head + i) % times.length];
        }
        values = v;
        times = t;
        head = 0;
    }
}
