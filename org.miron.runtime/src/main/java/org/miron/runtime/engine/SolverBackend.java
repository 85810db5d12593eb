package org.miron.runtime.engine;

import java.util.Map;

/**
 * Computes the decisions for one set of parameter values. Implementations: {@link MiniZincBackend}
 * (the {@code minizinc} process, the reference), {@link NativeBackend} (in process, the same decisions),
 * {@link CrossCheckBackend} (both, compared).
 * Called from one thread at a time; must not throw for solver trouble, only report it.
 */
public interface SolverBackend extends AutoCloseable {

    /** Short name reported in decisions and status, e.g. {@code minizinc}. */
    String name();

    /** Start-up check (binary present, model readable); the message must say what to fix. */
    void check() throws BackendUnavailableException;

    /** @param params MiniZinc parameter name → Double, Integer or Boolean */
    SolveResult solve(Map<String, Object> params);

    /** Backend-specific counters merged into {@code miron.status} after each solve (e.g. disagreements). */
    default Map<String, Long> counters() {
        return Map.of();
    }

    @Override
    default void close() {
    }
}
