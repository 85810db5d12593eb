package org.miron.runtime.engine;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.TimeUnit;

/**
 * The MiniZinc parameter values the next solve will use. Fixed size (one slot per parameter),
 * so however fast inputs arrive memory stays bounded; a version number tells the solve loop that
 * something changed, and the loop always takes the latest values (coalescing).
 */
public final class InputState {
    private final Map<String, Object> params = new LinkedHashMap<>();
    private long version = 1; // > 0 so the initial solve runs

    public InputState(IoModel model) {
        for (InputSpec in : model.inputs()) {
            if (in.isMetric()) {
                params.put(in.param(), in.initial());
            } else {
                params.put(in.param(), in.neutral());
                params.put(in.known(), Boolean.FALSE);
            }
        }
        for (VariationPoint vp : model.varpoints()) {
            params.put(vp.input(), Boolean.FALSE);
            params.put(vp.inputValue(), 0);
            params.put(vp.current(), vp.initial() == null ? -1 : vp.initial()); // the robot starts there
        }
    }

    /** A consistent copy of the parameters and the version it reflects. */
    public record Snapshot(long version, Map<String, Object> params) {
    }

    public synchronized void setMetric(InputSpec in, double value) {
        set(in.param(), value);
    }

    public synchronized void setContext(InputSpec in, Object value) {
        set(in.param(), value);
        set(in.known(), Boolean.TRUE);
    }

    /** Pins a varpoint to a value index, or releases it with {@code null}. */
    public synchronized void setOverride(VariationPoint vp, Integer index) {
        set(vp.input(), index != null);
        set(vp.inputValue(), index == null ? 0 : index);
    }

    /** Records the applied configuration; not an input change, so it schedules no solve. */
    public synchronized void setCurrent(VariationPoint vp, int index) {
        params.put(vp.current(), index);
    }

    private void set(String param, Object value) {
        if (!Objects.equals(params.put(param, value), value)) {
            version++;
            notifyAll();
        }
    }

    public synchronized long version() {
        return version;
    }

    /** Waits until the version differs from {@code seen}; returns the snapshot, or null on timeout. */
    public synchronized Snapshot awaitChange(long seen, long timeoutMs) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (version == seen) {
            long left = TimeUnit.NANOSECONDS.toMillis(end - System.nanoTime());
            if (left <= 0) {
                return null;
            }
            wait(left);
        }
        return snapshot();
    }

    public synchronized Snapshot snapshot() {
        return new Snapshot(version, Collections.unmodifiableMap(new LinkedHashMap<>(params)));
    }
}
