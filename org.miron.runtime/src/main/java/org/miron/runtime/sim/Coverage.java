package org.miron.runtime.sim;

import java.util.List;

/**
 * Which parts of a model a run exercised, or several runs merged (docs/simulator.md, "Coverage"):
 * per node of the woven tree its executions, SUCCESS and FAILURE endings and the missions that ran
 * it; per value of each enum varpoint ({@code task::dock}) the time it was in force; per rule the
 * decisions that applied it. An item is covered when it ran, was in force or applied at least once.
 * Items keep the model's order, so the same runs give the same output.
 */
public final class Coverage {
    public enum Kind {
        NODE, VARIANT, RULE
    }

    /** One line of the coverage: its kind, its name as MIRoN names it, its share in [0, 1] and whether it is covered. */
    public record Item(Kind kind, String name, double share, boolean covered) {
    }

    final List<String> nodes;
    final long[] ticked;
    final long[] succeeded;
    final long[] failed;
    final long[] missionsWith;
    long missions;
    final List<String> variants;
    final long[] heldMs;
    long durationMs;
    final List<String> rules;
    final long[] applied;
    long decisions;

    Coverage(List<String> nodes, List<String> variants, List<String> rules) {
        this.nodes = nodes;
        this.variants = variants;
        this.rules = rules;
        this.ticked = new long[nodes.size()];
        this.succeeded = new long[nodes.size()];
        this.failed = new long[nodes.size()];
        this.missionsWith = new long[nodes.size()];
        this.heldMs = new long[variants.size()];
        this.applied = new long[rules.size()];
    }

    /** The sum of runs of one setup (the same items); null for no runs. */
    public static Coverage merge(List<Coverage> runs) {
        if (runs.isEmpty()) {
            return null;
        }
        Coverage first = runs.get(0);
        Coverage sum = new Coverage(first.nodes, first.variants, first.rules);
        for (Coverage c : runs) {
            if (!c.nodes.equals(sum.nodes) || !c.variants.equals(sum.variants) || !c.rules.equals(sum.rules)) {
                throw new IllegalArgumentException("coverage of different models cannot be merged");
            }
            add(sum.ticked, c.ticked);
            add(sum.succeeded, c.succeeded);
            add(sum.failed, c.failed);
            add(sum.missionsWith, c.missionsWith);
            add(sum.heldMs, c.heldMs);
            add(sum.applied, c.applied);
            sum.missions += c.missions;
            sum.durationMs += c.durationMs;
            sum.decisions += c.decisions;
        }
        return sum;
    }

    private static void add(long[] into, long[] from) {
        for (int i = 0; i < into.length; i++) {
            into[i] += from[i];
        }
    }

    public List<String> nodes() {
        return nodes;
    }

    public long ticked(int node) {
        return ticked[node];
    }

    public long succeeded(int node) {
        return succeeded[node];
    }

    public long failed(int node) {
        return failed[node];
    }

    /** Missions (executions of the root) that ran this node at least once. */
    public long missionsWith(int node) {
        return missionsWith[node];
    }

    public long missions() {
        return missions;
    }

    public List<String> variants() {
        return variants;
    }

    public long heldMs(int variant) {
        return heldMs[variant];
    }

    public long durationMs() {
        return durationMs;
    }

    public List<String> rules() {
        return rules;
    }

    public long applied(int rule) {
        return applied[rule];
    }

    /** Solved decisions (each says which rules applied). */
    public long decisions() {
        return decisions;
    }

    /**
     * Every item in order, nodes then variants then rules, with its share: of the missions that ran
     * the node, of the time the value was in force, of the decisions that applied the rule.
     */
    public List<Item> items() {
        java.util.ArrayList<Item> out = new java.util.ArrayList<>(nodes.size() + variants.size() + rules.size());
        for (int i = 0; i < nodes.size(); i++) {
            out.add(new Item(Kind.NODE, nodes.get(i), ratio(missionsWith[i], missions), ticked[i] > 0));
        }
        for (int i = 0; i < variants.size(); i++) {
            out.add(new Item(Kind.VARIANT, variants.get(i), ratio(heldMs[i], durationMs), heldMs[i] > 0));
        }
        for (int i = 0; i < rules.size(); i++) {
            out.add(new Item(Kind.RULE, rules.get(i), ratio(applied[i], decisions), applied[i] > 0));
        }
        return out;
    }

    /** Covered items over all items, in [0, 1] (1 for a model with none). */
    public double coveredShare() {
        List<Item> all = items();
        return all.isEmpty() ? 1 : (double) covered() / all.size();
    }

    public int covered() {
        return (int) items().stream().filter(Item::covered).count();
    }

    public int size() {
        return nodes.size() + variants.size() + rules.size();
    }

    private static double ratio(long part, long whole) {
        return whole <= 0 ? 0 : (double) part / whole;
    }
}
