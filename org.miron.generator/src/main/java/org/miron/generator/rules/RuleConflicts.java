package org.miron.generator.rules;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.dsl.miron.Rule;
import org.miron.generator.AdaptationModel;
import org.miron.generator.SampledVariationPoint;

/**
 * The design-time rule check: over sampled situations (every combination of the values
 * {@link Situations} picks per input: each threshold the rules compare it with, just below and
 * above, and the values between; every enum literal, both Booleans), which rules apply, and does
 * the engine's priority search (keep rule k when it can hold with the higher rules kept so far)
 * have to drop any? A dropped rule gives a conflict: the smallest set of higher kept rules it
 * cannot hold with, plus the situation as a witness. Also rules that never apply and rules dropped
 * whenever they apply (shadowed). Bounded in time: past the budget the remaining situations are
 * not tried and every finding says so.
 */
public final class RuleConflicts {
    /** What the check found about one rule of the model. */
    public record Finding(Rule rule, String code, String message) {
    }

    private final AdaptationModel m;
    private final long budgetNanos;
    private final List<AdaptationModel.TranslatedRule> rules;
    private final TreeEvaluator eval;
    private final Map<String, Integer> sizes = new HashMap<>();
    /** Per rule: its consequences' constraints and the varpoints each reads (condition included). */
    private final List<List<JsonNode>> bodies = new ArrayList<>();
    private final List<List<List<String>>> bodyVars = new ArrayList<>();
    private final boolean[] conditionReadsVarpoints;
    private final Situations situations;
    private Feasibility search;
    /** When no consequence reads an input, what the priority search drops depends only on which rules apply. */
    private final boolean bodiesReadNoInput;
    private final Map<BitSet, List<int[]>> outcomes = new HashMap<>();
    private long tried;

    public RuleConflicts(AdaptationModel m, long budgetMillis) {
        this.m = m;
        this.budgetNanos = budgetMillis * 1_000_000L;
        this.rules = m.rules;
        for (SampledVariationPoint vp : m.varpoints) {
            sizes.put(vp.name, vp.size());
        }
        eval = TreeEvaluator.of(m.varpoints);
        conditionReadsVarpoints = new boolean[rules.size()];
        for (int r = 0; r < rules.size(); r++) {
            AdaptationModel.TranslatedRule rule = rules.get(r);
            Set<String> condVars = new LinkedHashSet<>();
            varpoints(rule.conditionTree(), condVars);
            conditionReadsVarpoints[r] = !condVars.isEmpty();
            List<JsonNode> b = new ArrayList<>();
            List<List<String>> vars = new ArrayList<>();
            for (AdaptationModel.Consequence c : rule.consequences()) {
                Set<String> reads = new LinkedHashSet<>(condVars);
                varpoints(c.tree(), reads);
                b.add(c.tree());
                vars.add(new ArrayList<>(reads));
            }
            bodies.add(b);
            bodyVars.add(vars);
        }
        situations = new Situations(m);
        boolean readsInput = false;
        for (AdaptationModel.TranslatedRule rule : rules) {
            for (AdaptationModel.Consequence c : rule.consequences()) {
                Set<String> params = new LinkedHashSet<>();
                params(c.tree(), params);
                readsInput |= !params.isEmpty();
            }
        }
        bodiesReadNoInput = !readsInput;
    }

    private static void varpoints(JsonNode n, Set<String> into) {
        if (n == null) {
            return;
        }
        if (n.has("index")) {
            into.add(n.get("index").asText());
        } else if (n.has("value")) {
            into.add(n.get("value").asText());
        }
        n.path("args").forEach(a -> varpoints(a, into));
    }

    public List<Finding> analyse() {
        int n = rules.size();
        int[] applies = new int[n];
        int[] dropped = new int[n];
        Map<String, Conflict> conflicts = new LinkedHashMap<>();
        Map<Integer, Set<Integer>> overriders = new HashMap<>();
        long start = System.nanoTime();
        search = new Feasibility(eval, sizes, start + budgetNanos);
        long total = situations.count();
        tried = 0;
        for (long s = 0; s < total; s++) {
            if (System.nanoTime() - start > budgetNanos) {
                break;
            }
            try {
                situation(s, applies, dropped, conflicts, overriders);
            } catch (Feasibility.OutOfTime e) {
                break;
            }
            tried++;
        }
        boolean cut = tried < total;
        String note = cut ? " (rule check stopped after " + budgetNanos / 1_000_000 + " ms: " + tried + " of " + total
                + " situations tried)" : "";
        List<Finding> findings = new ArrayList<>();
        boolean[] shadowed = new boolean[n];
        for (int r = 0; r < n && !cut; r++) { // "never" and "always" need every situation
            String name = rules.get(r).rule().getName();
            if (applies[r] == 0) {
                findings.add(new Finding(rules.get(r).rule(), "miron.rule-never-applies", "rule " + name
                        + " never applies: its condition is false in every situation (" + tried + " tried)"));
            } else if (dropped[r] == applies[r] && overriders.get(r) == null) {
                shadowed[r] = true;
                findings.add(new Finding(rules.get(r).rule(), "miron.rule-conflict", "rule " + name
                        + " can never hold: its consequences contradict each other"));
            } else if (dropped[r] == applies[r]) {
                shadowed[r] = true;
                findings.add(new Finding(rules.get(r).rule(), "miron.rule-shadowed", "rule " + name
                        + " is always overridden by " + names(overriders.get(r)) + ": whenever it applies it conflicts with "
                        + (overriders.get(r).size() == 1 ? "that higher rule" : "those higher rules")));
            }
        }
        for (Conflict c : conflicts.values()) {
            int loser = c.rules.length() - 1;
            if (shadowed[loser] || c.rules.cardinality() < 2) {
                continue;
            }
            BitSet winners = (BitSet) c.rules.clone();
            winners.clear(loser);
            Set<Integer> all = new LinkedHashSet<>();
            c.rules.stream().forEach(all::add);
            Set<Integer> win = new LinkedHashSet<>();
            winners.stream().forEach(win::add);
            findings.add(new Finding(rules.get(loser).rule(), "miron.rule-conflict", "rules " + names(all)
                    + " conflict when " + situations.describe(c.witness, conditionInputs(c.rules)) + "; " + names(win)
                    + (win.size() == 1 ? " wins" : " win") + note));
        }
        if (cut && findings.isEmpty() && !rules.isEmpty()) {
            findings.add(new Finding(rules.get(0).rule(), "miron.rule-check-cut", "rule check stopped after "
                    + budgetNanos / 1_000_000 + " ms: " + tried + " of " + total
                    + " situations tried without a conflict; the others were not checked"));
        }
        return findings;
    }

    /** Tries one situation: which rules apply, which the priority search drops, and why. */
    private void situation(long s, int[] applies, int[] dropped, Map<String, Conflict> conflicts,
            Map<Integer, Set<Integer>> overriders) {
        int n = rules.size();
        Map<String, Double> in = situations.get(s);
        BitSet applying = new BitSet();
        for (int r = 0; r < n; r++) {
            if (conditionReadsVarpoints[r] || eval.holds(rules.get(r).conditionTree(), in, Map.of())) {
                applying.set(r);
                applies[r]++;
            }
        }
        List<int[]> known = bodiesReadNoInput ? outcomes.get(applying) : null;
        if (known != null) { // the same rules applied before: the same drops, an earlier witness
            for (int[] drop : known) {
                dropped[drop[0]]++;
            }
            return;
        }
        List<int[]> drops = new ArrayList<>();
        BitSet kept = new BitSet();
        for (int r = applying.nextSetBit(0); r >= 0; r = applying.nextSetBit(r + 1)) {
            kept.set(r);
            if (feasible(kept, in)) {
                continue;
            }
            kept.clear(r);
            dropped[r]++;
            drops.add(new int[] {r});
            int loser = r;
            BitSet set = minimal(kept.get(0, r), r, in);
            set.stream().filter(x -> x != loser)
                    .forEach(x -> overriders.computeIfAbsent(loser, k -> new LinkedHashSet<>()).add(x));
            conflicts.computeIfAbsent(set.toString(), k -> new Conflict(set, in));
        }
        if (bodiesReadNoInput) {
            outcomes.put(applying, drops);
        }
    }

    /** Situations the last {@link #analyse()} tried. */
    public long tried() {
        return tried;
    }

    /** Situations there are to try. */
    public long situations() {
        return situations.count();
    }

    private record Conflict(BitSet rules, Map<String, Double> witness) {
    }

    /** Inputs read by the conditions of these rules, in rule order. */
    private List<String> conditionInputs(BitSet set) {
        Set<String> params = new LinkedHashSet<>();
        set.stream().forEach(r -> params(rules.get(r).conditionTree(), params));
        return new ArrayList<>(params);
    }

    private static void params(JsonNode n, Set<String> into) {
        if (n == null) {
            return;
        }
        if (n.has("param")) {
            into.add(n.get("param").asText());
        }
        n.path("args").forEach(a -> params(a, into));
    }

    private String names(Set<Integer> set) {
        List<String> names = new ArrayList<>();
        set.forEach(r -> names.add(rules.get(r).rule().getName()));
        if (names.size() == 1) {
            return names.get(0);
        }
        return String.join(", ", names.subList(0, names.size() - 1)) + " and " + names.get(names.size() - 1);
    }

    /** The smallest subset of {@code higher} that {@code rule} cannot hold with (deletion, lowest first). */
    private BitSet minimal(BitSet higher, int rule, Map<String, Double> in) {
        BitSet set = (BitSet) higher.clone();
        set.set(rule);
        for (int h = higher.length() - 1; h >= 0; h--) {
            if (!set.get(h) || h == rule) {
                continue;
            }
            set.clear(h);
            if (feasible(set, in)) {
                set.set(h);
            }
        }
        return set;
    }

    /** Whether some assignment of the varpoints satisfies every consequence of these rules. */
    private boolean feasible(BitSet set, Map<String, Double> in) {
        List<Feasibility.Guarded> constraints = new ArrayList<>();
        set.stream().forEach(r -> {
            for (int c = 0; c < bodies.get(r).size(); c++) {
                constraints.add(new Feasibility.Guarded(rules.get(r).conditionTree(), bodies.get(r).get(c),
                        bodyVars.get(r).get(c)));
            }
        });
        return search.feasible(constraints, in);
    }
}
