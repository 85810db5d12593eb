package org.miron.runtime.engine;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * Rule priority for a backend that solves one set of parameters (the {@code minizinc} process):
 * first every rule kept; if that is unsatisfiable, the rules are kept greedily in priority order
 * (rule k is kept when it can hold with the higher rules kept so far), which is the
 * lexicographically best set of kept rules, and the decision of the last satisfiable probe (whose
 * kept set is the final one) is the answer. {@link NativeBackend} runs the same search in process.
 * Only when no rule is kept and it is still unsatisfiable (the domains, e.g. an override pinned
 * outside the values) is the result UNSAT.
 */
final class RulePriority {
    private RulePriority() {
    }

    static SolveResult solve(List<RuleSpec> rules, Map<String, Object> params,
            Function<Map<String, Object>, SolveResult> once) {
        if (rules.isEmpty()) {
            return once.apply(params);
        }
        Map<String, Object> p = new HashMap<>(params);
        rules.forEach(r -> p.put(r.keep(), true));
        SolveResult r = once.apply(p);
        if (r.status() != SolveResult.Status.UNSAT) {
            return r;
        }
        long millis = r.millis();
        rules.forEach(rule -> p.put(rule.keep(), false));
        SolveResult lastSolved = null;
        List<String> dropped = new ArrayList<>();
        for (RuleSpec rule : rules) {
            p.put(rule.keep(), true);
            SolveResult probe = once.apply(p);
            millis += probe.millis();
            if (probe.solved()) {
                lastSolved = probe;
            } else if (probe.status() == SolveResult.Status.UNSAT) {
                p.put(rule.keep(), false);
                dropped.add(rule.name());
            } else {
                return probe; // timeout or error: nothing to conclude
            }
        }
        if (lastSolved == null) { // every rule dropped: only the domains are left
            lastSolved = once.apply(p);
            millis += lastSolved.millis();
            if (!lastSolved.solved()) {
                return SolveResult.failed(lastSolved.status(), lastSolved.message(), millis);
            }
        }
        return new SolveResult(SolveResult.Status.SOLVED, lastSolved.decisions(), lastSolved.optimal(), "", millis,
                List.copyOf(dropped));
    }

    /** The parameters a solve that dropped {@code dropped} ran with (every other rule kept). */
    static Map<String, Object> withKeeps(List<RuleSpec> rules, Map<String, Object> params, List<String> dropped) {
        Map<String, Object> p = new HashMap<>(params);
        rules.forEach(r -> p.put(r.keep(), !dropped.contains(r.name())));
        return p;
    }
}
