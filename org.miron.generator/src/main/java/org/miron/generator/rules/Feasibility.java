package org.miron.generator.rules;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Whether some assignment of the varpoints satisfies a set of guarded constraints ({@code guard ->
 * body}) in one situation: constraints reading no varpoint are evaluated, those reading one filter
 * its values, and the varpoints linked by the others are searched depth-first, group by group
 * (unlinked groups are independent), each constraint checked once its last varpoint is assigned.
 * Gives up with {@link OutOfTime} past the deadline.
 */
final class Feasibility {
    /** The rule check's budget ran out in the middle of a search. */
    static final class OutOfTime extends RuntimeException {
        OutOfTime() {
            super(null, null, false, false);
        }
    }

    /** One consequence: its rule's condition, its constraint and the varpoints both read. */
    record Guarded(JsonNode guard, JsonNode body, List<String> reads) {
    }

    private final TreeEvaluator eval;
    private final Map<String, Integer> sizes;
    private final long deadline;
    private long steps;

    Feasibility(TreeEvaluator eval, Map<String, Integer> sizes, long deadlineNanos) {
        this.eval = eval;
        this.sizes = sizes;
        this.deadline = deadlineNanos;
    }

    boolean feasible(List<Guarded> constraints, Map<String, Double> in) {
        if (System.nanoTime() > deadline) {
            throw new OutOfTime();
        }
        Map<String, boolean[]> allowed = new HashMap<>();
        List<Guarded> linked = new ArrayList<>();
        for (Guarded c : constraints) {
            if (c.reads().isEmpty()) {
                if (eval.holds(c.guard(), in, Map.of()) && !eval.holds(c.body(), in, Map.of())) {
                    return false;
                }
            } else if (c.reads().size() == 1) {
                String vp = c.reads().get(0);
                boolean[] ok = allowed.computeIfAbsent(vp, k -> filled(sizes.get(k)));
                Map<String, Integer> assign = new HashMap<>();
                boolean any = false;
                for (int i = 0; i < ok.length; i++) {
                    if (ok[i]) {
                        assign.put(vp, i);
                        ok[i] = !eval.holds(c.guard(), in, assign) || eval.holds(c.body(), in, assign);
                    }
                    any |= ok[i];
                }
                if (!any) {
                    return false;
                }
            } else {
                linked.add(c);
            }
        }
        for (List<Guarded> group : groups(linked)) {
            List<String> order = new ArrayList<>();
            group.forEach(c -> c.reads().forEach(v -> {
                if (!order.contains(v)) {
                    order.add(v);
                }
            }));
            List<List<Guarded>> checkAt = new ArrayList<>();
            order.forEach(v -> checkAt.add(new ArrayList<>()));
            for (Guarded c : group) {
                int last = 0;
                for (String v : c.reads()) {
                    last = Math.max(last, order.indexOf(v));
                }
                checkAt.get(last).add(c);
            }
            if (!search(order, checkAt, 0, new HashMap<>(), allowed, in)) {
                return false;
            }
        }
        return true;
    }

    private boolean search(List<String> order, List<List<Guarded>> checkAt, int depth, Map<String, Integer> assign,
            Map<String, boolean[]> allowed, Map<String, Double> in) {
        if (depth == order.size()) {
            return true;
        }
        if ((++steps & 1023) == 0 && System.nanoTime() > deadline) {
            throw new OutOfTime();
        }
        String vp = order.get(depth);
        boolean[] ok = allowed.get(vp);
        for (int i = 0; i < sizes.get(vp); i++) {
            if (ok != null && !ok[i]) {
                continue;
            }
            assign.put(vp, i);
            boolean holds = true;
            for (Guarded c : checkAt.get(depth)) {
                if (eval.holds(c.guard(), in, assign) && !eval.holds(c.body(), in, assign)) {
                    holds = false;
                    break;
                }
            }
            if (holds && search(order, checkAt, depth + 1, assign, allowed, in)) {
                assign.remove(vp);
                return true;
            }
        }
        assign.remove(vp);
        return false;
    }

    /** The constraints grouped by the varpoints they link (union-find on names). */
    private static List<List<Guarded>> groups(List<Guarded> linked) {
        Map<String, String> parent = new HashMap<>();
        for (Guarded c : linked) {
            String first = root(parent, c.reads().get(0));
            for (String v : c.reads()) {
                parent.put(root(parent, v), first);
            }
        }
        Map<String, List<Guarded>> groups = new LinkedHashMap<>();
        for (Guarded c : linked) {
            groups.computeIfAbsent(root(parent, c.reads().get(0)), k -> new ArrayList<>()).add(c);
        }
        return new ArrayList<>(groups.values());
    }

    private static String root(Map<String, String> parent, String v) {
        String p = parent.getOrDefault(v, v);
        while (!p.equals(parent.getOrDefault(p, p))) {
            p = parent.getOrDefault(p, p);
        }
        return p;
    }

    private static boolean[] filled(int n) {
        boolean[] a = new boolean[n];
        java.util.Arrays.fill(a, true);
        return a;
    }
}
