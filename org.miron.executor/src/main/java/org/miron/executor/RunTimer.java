package org.miron.executor;

/**
 * Time since a node's first tick of its current run, read from the tree's clock at tick time (so
 * runs are deterministic under a fake clock); shared by the nodes that wait (Timeout, Delay).
 */
public final class RunTimer {
    private boolean running;
    private long startMillis;

    /** True before the first {@link #elapsed} of a run. */
    public boolean isIdle() {
        return !running;
    }

    /** Milliseconds since the first call of this run; the first call starts the run and returns 0. */
    public long elapsed(MillisClock clock) {
        long now = clock.nowMillis();
        if (!running) {
            running = true;
            startMillis = now;
        }
        return now - startMillis;
    }

    /** Ends the run: the next {@link #elapsed} starts a new one. */
    public void reset() {
        running = false;
    }
}
