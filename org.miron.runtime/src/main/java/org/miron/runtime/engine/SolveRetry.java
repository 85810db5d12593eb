package org.miron.runtime.engine;

/**
 * When to solve again after a failed solve although no input changed. A timeout or a crash
 * (status TIMEOUT or ERROR) may be transient: a loaded machine, a killed solver, a model file
 * being replaced. Without a retry the engine would keep the old configuration for as long as the
 * inputs stay the same. UNSAT is a property of the model and the inputs, so it is not retried.
 * The delay doubles from {@code minMs} to {@code maxMs} and is reset by any completed solve.
 * Solve thread only.
 */
final class SolveRetry {
    private final long minMs;
    private final long maxMs;
    private long delayMs;
    private long dueNanos = -1; // -1: nothing to retry

    SolveRetry(long minMs, long maxMs) {
        this.minMs = Math.max(1, minMs);
        this.maxMs = Math.max(this.minMs, maxMs);
        this.delayMs = this.minMs;
    }

    /** Records a solve outcome: schedules the next retry after a transient failure, clears it otherwise. */
    void after(SolveResult r) {
        boolean transientFailure = r.status() == SolveResult.Status.TIMEOUT || r.status() == SolveResult.Status.ERROR;
        if (!transientFailure) {
            dueNanos = -1;
            delayMs = minMs;
            return;
        }
        dueNanos = System.nanoTime() + delayMs * 1_000_000L;
        delayMs = Math.min(maxMs, delayMs * 2);
    }

    boolean pending() {
        return dueNanos != -1;
    }

    boolean due() {
        return pending() && System.nanoTime() - dueNanos >= 0;
    }

    /** How long the loop may wait for an input before the retry is due (at most {@code capMs}). */
    long waitMs(long capMs) {
        if (!pending()) {
            return capMs;
        }
        return Math.max(1, Math.min(capMs, (dueNanos - System.nanoTime()) / 1_000_000L));
    }

    /** The delay that the next failure will wait (reported in the status message). */
    long nextDelayMs() {
        return delayMs;
    }
}
