package org.miron.runtime.engine;

import java.util.Map;
import java.util.logging.Logger;

/**
 * {@code --backend both}: every solve runs on the reference (MiniZinc) and on the candidate
 * (native); the reference's answer is used, and a different outcome or decision is logged and
 * counted ({@code disagreements} in {@code miron.status}).
 */
public final class CrossCheckBackend implements SolverBackend {
    private static final Logger LOG = Logger.getLogger(CrossCheckBackend.class.getName());

    private final SolverBackend reference;
    private final SolverBackend candidate;
    private volatile long disagreements; // written by the solve thread, read for status

    public CrossCheckBackend(SolverBackend reference, SolverBackend candidate) {
        this.reference = reference;
        this.candidate = candidate;
    }

    @Override
    public String name() {
        return "both";
    }

    @Override
    public void check() throws BackendUnavailableException {
        reference.check();
        candidate.check();
    }

    @Override
    public SolveResult solve(Map<String, Object> params) {
        SolveResult expected = reference.solve(params);
        SolveResult actual = candidate.solve(params);
        if (comparable(expected) && !agree(expected, actual)) {
            disagreements++;
            LOG.warning("backends disagree: " + reference.name() + " " + describe(expected) + ", " + candidate.name()
                    + " " + describe(actual) + ", inputs " + params);
        }
        return expected;
    }

    /** A reference timeout or crash says nothing about the candidate. */
    private static boolean comparable(SolveResult r) {
        return r.status() == SolveResult.Status.SOLVED || r.status() == SolveResult.Status.UNSAT;
    }

    static boolean agree(SolveResult a, SolveResult b) {
        return a.status() == b.status() && a.decisions().equals(b.decisions()) && a.dropped().equals(b.dropped());
    }

    private static String describe(SolveResult r) {
        return r.solved() ? r.decisions() + (r.dropped().isEmpty() ? "" : " dropping " + r.dropped()) : r.status() + " (" + r.message() + ")";
    }

    @Override
    public Map<String, Long> counters() {
        return Map.of("disagreements", disagreements);
    }

    @Override
    public void close() {
        reference.close();
        candidate.close();
    }
}
