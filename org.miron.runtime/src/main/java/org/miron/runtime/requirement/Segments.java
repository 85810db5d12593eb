package org.miron.runtime.requirement;

import java.util.Arrays;

/**
 * A Boolean signal over integer milliseconds as consecutive segments {@code [start, end)}, each with
 * one truth value, known up to {@link #horizon()}. Appended at the end in time order, dropped at
 * the front once the reader no longer needs them: what stays is what the windows above still look
 * at, never the whole run. Adjacent segments of the same value are merged.
 */
final class Segments {
    private long[] starts = new long[8];
    private Truth[] values = new Truth[8];
    private int head;
    private int size;
    private long horizon;

    long horizon() {
        return horizon;
    }

    int size() {
        return size;
    }

    long start(int i) {
        return starts[head + i];
    }

    long end(int i) {
        return i + 1 < size ? starts[head + i + 1] : horizon;
    }

    Truth value(int i) {
        return values[head + i];
    }

    /** Extends the signal by {@code [from, to)} with value {@code v}; {@code from} is the horizon. */
    void append(long from, long to, Truth v) {
        if (from != horizon || to <= from) {
            throw new IllegalStateException("segment [" + from + ", " + to + ") does not extend a signal known up to " + horizon);
        }
        horizon = to;
        if (size > 0 && values[head + size - 1] == v) {
            return;
        }
        if (head + size == starts.length) {
            if (head > starts.length / 2) { // reuse the dropped front
                System.arraycopy(starts, head, starts, 0, size);
                System.arraycopy(values, head, values, 0, size);
                head = 0;
            } else {
                starts = Arrays.copyOf(starts, starts.length * 2);
                values = Arrays.copyOf(values, values.length * 2);
            }
        }
        starts[head + size] = from;
        values[head + size] = v;
        size++;
    }

    /** Drops the segments that end at or before {@code t}. */
    void dropBefore(long t) {
        while (size > 0 && end(0) <= t) {
            values[head] = null;
            head++;
            size--;
        }
        if (size == 0) {
            head = 0;
        }
    }

    /** Index of the last segment of value {@code v}, or -1. */
    int lastOf(Truth v) {
        for (int i = size - 1; i >= 0; i--) {
            if (value(i) == v) {
                return i;
            }
        }
        return -1;
    }
}
