package org.miron.runtime.engine;

import java.util.List;
import java.util.Map;

/**
 * Outcome of one solve.
 *
 * @param decisions varpoint decision variable ({@code <vp>_var}) → value index; empty unless SOLVED
 * @param optimal   the solver proved the solution optimal (or it is a satisfy model's solution)
 * @param message   diagnostics for failures
 * @param dropped   names of the rules dropped because they could not hold with higher ones, in
 *                  priority order; empty when every applicable rule holds
 */
public record SolveResult(Status status, Map<String, Integer> decisions, boolean optimal, String message, long millis,
        List<String> dropped) {

    public SolveResult(Status status, Map<String, Integer> decisions, boolean optimal, String message, long millis) {
        this(status, decisions, optimal, message, millis, List.of());
    }

    public enum Status { SOLVED, UNSAT, TIMEOUT, ERROR }

    public static SolveResult failed(Status status, String message, long millis) {
        return new SolveResult(status, Map.of(), false, message, millis);
    }

    public boolean solved() {
        return status == Status.SOLVED;
    }
}
