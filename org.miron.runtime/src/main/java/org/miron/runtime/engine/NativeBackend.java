package org.miron.runtime.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Decides in process, with exactly the semantics of the generated MiniZinc model (docs/io-json.md,
 * "decision"): a consequence constrains while its overrides are off, its contexts known and its
 * condition true; the objective is {@code scale * gain + tie} summed over varpoints, so each group
 * of varpoints linked by rules (a {@link NativeModel} component) is optimised on its own.
 * Consequences reading one varpoint filter its values; linked varpoints are searched depth-first
 * in declaration order, values ascending (MiniZinc's order, so among equal optima the same,
 * lexicographically first, one wins), pruned by the per-varpoint maxima of the rest. Without
 * impacts (satisfy) values are tried preset, current, then ascending, as the .mzn's search does.
 * All working arrays are allocated once; a solve allocates nothing but a new result when the
 * decisions (or the whole milliseconds it took) differ from the previous solve's, whose result,
 * immutable, is returned again otherwise: the steady state allocates nothing.
 *
 * <p>Rule priority (as {@link RulePriority} does with MiniZinc): all rules kept first; when that has
 * no solution, rule k is kept when it can hold with the higher rules kept so far, the others are
 * dropped (reported in the result), and the optimum under the kept rules is the decision.
 */
public final class NativeBackend implements SolverBackend {
    private final NativeModel m;
    private final double[] param;
    private final boolean[][] allowed;
    private final long[][] score;
    private final int[][] order;
    private final int[] assign;
    private final int[] best;
    private final boolean[] active;
    /** Per rule (priority order): kept (its consequences constrain) or dropped for higher ones. */
    private final boolean[] keep;
    private final int[] keptBest;
    /** Per varpoint: the multi-varpoint constraints checked once it (their last varpoint) is assigned. */
    private final int[][] checkAt;
    private final long[] suffix;
    private long bestValue;
    private boolean found;
    /** The previous SOLVED result and its decisions, returned again when nothing differs. */
    private SolveResult last;
    private final int[] lastBest;
    private SolveResult lastUnsat;

    public NativeBackend(IoModel io) {
        m = new NativeModel(io);
        int n = m.varpointCount;
        param = new double[m.paramNames.length];
        allowed = new boolean[n][];
        score = new long[n][];
        order = new int[n][];
        for (int v = 0; v < n; v++) {
            allowed[v] = new boolean[m.sizes[v]];
            score[v] = new long[m.sizes[v]];
            order[v] = new int[m.sizes[v]];
        }
        assign = new int[n];
        best = new int[n];
        lastBest = new int[n];
        suffix = new long[n + 1];
        active = new boolean[m.constraints.length];
        keep = new boolean[m.ruleNames.length];
        keptBest = new int[n];
        checkAt = new int[n][];
        for (int v = 0; v < n; v++) {
            final int last = v;
            checkAt[v] = java.util.stream.IntStream.range(0, m.constraints.length)
                    .filter(c -> m.constraints[c].vars().length > 1
                            && m.constraints[c].vars()[m.constraints[c].vars().length - 1] == last)
                    .toArray();
        }
    }

    @Override
    public String name() {
        return "native";
    }

    @Override
    public void check() {
        // compiled in the constructor: nothing external to check
    }

    @Override
    public SolveResult solve(Map<String, Object> params) {
        long start = System.nanoTime();
        String missing = read(params);
        if (missing != null) {
            return SolveResult.failed(SolveResult.Status.ERROR, "no value for parameter " + missing, millisSince(start));
        }
        scores();
        Arrays.fill(keep, true);
        boolean solved = solveKept();
        int dropped = 0;
        if (!solved && m.prioritised && keep.length > 0) {
            Arrays.fill(keep, false);
            for (int r = 0; r < keep.length; r++) {
                keep[r] = true;
                if (solveKept()) {
                    solved = true;
                    System.arraycopy(best, 0, keptBest, 0, best.length);
                } else {
                    keep[r] = false;
                    dropped++;
                }
            }
            if (solved) {
                System.arraycopy(keptBest, 0, best, 0, best.length);
            } else {
                solved = solveKept(); // every rule dropped: only the domains are left
            }
        }
        if (!solved) {
            return unsat(start);
        }
        long millis = millisSince(start);
        if (dropped == 0 && last != null && last.millis() == millis && Arrays.equals(best, lastBest)) {
            return last;
        }
        Map<String, Integer> decisions = new LinkedHashMap<>();
        for (int v = 0; v < m.varpointCount; v++) {
            decisions.put(m.decisionNames[v], best[v]);
        }
        System.arraycopy(best, 0, lastBest, 0, best.length);
        List<String> droppedNames = new ArrayList<>(dropped);
        for (int r = 0; r < keep.length && dropped > 0; r++) {
            if (!keep[r]) {
                droppedNames.add(m.ruleNames[r]);
            }
        }
        SolveResult result = new SolveResult(SolveResult.Status.SOLVED, Collections.unmodifiableMap(decisions), true, "",
                millis, List.copyOf(droppedNames));
        if (dropped == 0) {
            last = result;
        }
        return result;
    }

    /** Optimises every component into {@code best} under the kept rules; false when one has no solution. */
    private boolean solveKept() {
        if (!domains() || !filter()) {
            return false;
        }
        for (int[] component : m.components) {
            if (!search(component)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The .mzn's objective ({@code scale * gain + tie}) of a given decision under these inputs, or
     * null when it breaks a constraint: tells an alternative optimum (equal objective, a tie the
     * model leaves to the solver's search) from a real difference.
     */
    public Long objective(Map<String, Object> params, Map<String, Integer> decisions) {
        return objective(params, decisions, List.of());
    }

    /** The objective with the named rules dropped (as a solve that reported them dropped). */
    public Long objective(Map<String, Object> params, Map<String, Integer> decisions, List<String> dropped) {
        for (int r = 0; r < keep.length; r++) {
            keep[r] = !dropped.contains(m.ruleNames[r]);
        }
        if (read(params) != null || !domains()) {
            return null;
        }
        for (int v = 0; v < m.varpointCount; v++) {
            Integer i = decisions.get(m.decisionNames[v]);
            if (i == null || i < 0 || i >= m.sizes[v] || !allowed[v][i]) {
                return null;
            }
            assign[v] = i;
        }
        for (NativeModel.Constraint k : m.constraints) {
            if (guarded(k) && violated(k)) {
                return null;
            }
        }
        scores();
        long total = 0;
        for (int v = 0; v < m.varpointCount; v++) {
            total += score[v][assign[v]];
        }
        return total;
    }

    private SolveResult unsat(long start) {
        long millis = millisSince(start);
        if (lastUnsat == null || lastUnsat.millis() != millis) {
            lastUnsat = SolveResult.failed(SolveResult.Status.UNSAT, "model is unsatisfiable", millis);
        }
        return lastUnsat;
    }

    /** Copies the parameters into their slots; returns the name of a missing one, or null. */
    private String read(Map<String, Object> params) {
        return m.readParams(params, param);
    }

    /** Every value, or only the pinned one under an override; false when a pin is out of range. */
    private boolean domains() {
        for (int v = 0; v < m.varpointCount; v++) {
            if (param[m.inputSlot[v]] == 1) {
                int pinned = (int) param[m.inputValueSlot[v]];
                if (pinned < 0 || pinned >= m.sizes[v]) {
                    return false;
                }
                Arrays.fill(allowed[v], false);
                allowed[v][pinned] = true;
            } else {
                Arrays.fill(allowed[v], true);
            }
        }
        return true;
    }

    /** Decides which constraints apply; those reading at most one varpoint are applied now. */
    private boolean filter() {
        for (int c = 0; c < m.constraints.length; c++) {
            NativeModel.Constraint k = m.constraints[c];
            active[c] = guarded(k);
            if (!active[c] || k.vars().length > 1) {
                continue;
            }
            active[c] = false;
            if (k.vars().length == 0) {
                if (violated(k)) {
                    return false;
                }
                continue;
            }
            int v = k.vars()[0];
            for (int i = 0; i < m.sizes[v]; i++) {
                if (allowed[v][i]) {
                    assign[v] = i;
                    allowed[v][i] = !violated(k);
                }
            }
        }
        return true;
    }

    /** The guard's part that reads no varpoint: no override on what it constrains, contexts known. */
    private boolean guarded(NativeModel.Constraint k) {
        if (!keep[k.rule()]) {
            return false;
        }
        for (int vp : k.overrides()) {
            if (param[m.inputSlot[vp]] == 1) {
                return false;
            }
        }
        for (int slot : k.known()) {
            if (param[slot] != 1) {
                return false;
            }
        }
        return true;
    }

    private boolean violated(NativeModel.Constraint k) {
        return m.pool.holds(k.condition(), param, assign) && !m.pool.holds(k.body(), param, assign);
    }

    /**
     * Per value: tie_scale * gain + tie, as the .mzn's objective (gain: round(100 * sum of weight *
     * utility), summed in the same order so the doubles are the same). Satisfy: 0, and the values
     * in the .mzn's search order.
     */
    private void scores() {
        long scale = 3L * m.varpointCount + 1;
        for (int v = 0; v < m.varpointCount; v++) {
            int n = m.sizes[v];
            int preset = m.preset[v];
            int current = (int) param[m.currentSlot[v]];
            if (!m.maximize) {
                Arrays.fill(score[v], 0);
                int k = 0;
                if (preset >= 0 && preset < n) {
                    order[v][k++] = preset;
                }
                if (current >= 0 && current < n && current != preset) {
                    order[v][k++] = current;
                }
                for (int i = 0; i < n; i++) {
                    if (i != preset && i != current) {
                        order[v][k++] = i;
                    }
                }
                continue;
            }
            int[] metrics = m.utilityMetric[v];
            for (int i = 0; i < n; i++) {
                long gain = 0;
                if (metrics.length > 0) {
                    double sum = weight(metrics[0]) * m.utilityTable[v][0][i];
                    for (int u = 1; u < metrics.length; u++) {
                        sum = sum + weight(metrics[u]) * m.utilityTable[v][u][i];
                    }
                    gain = round(100.0 * sum);
                }
                score[v][i] = scale * gain + (i == preset ? 2 : 0) + (i == current ? 1 : 0);
                order[v][i] = i;
            }
        }
    }

    private double weight(int metricSlot) {
        return m.weightIsNeed ? 1.0 - param[metricSlot] : param[metricSlot];
    }

    /** MiniZinc's round (C's llround): half away from zero. */
    static long round(double x) {
        double a = Math.abs(x);
        double f = Math.floor(a);
        long r = (long) (a - f >= 0.5 ? f + 1 : f);
        return x < 0 ? -r : r;
    }

    /** Optimises one component into {@code best}; false when it has no solution. */
    private boolean search(int[] component) {
        suffix[component.length] = 0;
        for (int k = component.length - 1; k >= 0; k--) {
            int v = component[k];
            long max = Long.MIN_VALUE;
            for (int i = 0; i < m.sizes[v]; i++) {
                if (allowed[v][i] && score[v][i] > max) {
                    max = score[v][i];
                }
            }
            if (max == Long.MIN_VALUE) {
                return false;
            }
            suffix[k] = suffix[k + 1] + max;
        }
        bestValue = Long.MIN_VALUE;
        found = false;
        dfs(component, 0, 0);
        return found;
    }

    private void dfs(int[] component, int depth, long partial) {
        if (depth == component.length) {
            bestValue = partial;
            found = true;
            for (int v : component) {
                best[v] = assign[v];
            }
            return;
        }
        int v = component[depth];
        for (int i : order[v]) {
            if (!allowed[v][i]) {
                continue;
            }
            long value = partial + score[v][i];
            if (found && value + suffix[depth + 1] <= bestValue) {
                continue; // cannot beat the best strictly: an equal one found later is not preferred
            }
            assign[v] = i;
            if (consistent(v)) {
                dfs(component, depth + 1, value);
            }
        }
    }

    private boolean consistent(int v) {
        for (int c : checkAt[v]) {
            if (active[c] && violated(m.constraints[c])) {
                return false;
            }
        }
        return true;
    }

    private static long millisSince(long startNanos) {
        return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - startNanos);
    }
}
