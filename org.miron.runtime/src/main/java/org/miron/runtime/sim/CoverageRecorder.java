package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.trace.StatusListener;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.VariationPoint;

/**
 * Fills one run's {@link Coverage}: a status listener on the tree, the decisions' applied rules and
 * the enum varpoints' values over time. Every index is found once at construction, so a status
 * change costs a map look-up and two increments and allocates nothing.
 */
final class CoverageRecorder implements StatusListener {
    private final Coverage counts;
    private final Node root;
    private final IdentityHashMap<Node, Integer> nodeIndex = new IdentityHashMap<>();
    /** The mission that last ran node i: counts each mission once per node. */
    private final long[] lastMission;
    /** Per enum varpoint's name: its position k in {@link #first}, {@link #current} and {@link #since}. */
    private final Map<String, Integer> enumIndex = new HashMap<>();
    /** Per enum varpoint: the index of its first value among the variants, the variant in force (-1: none) and since when. */
    private final int[] first;
    private final int[] current;
    private final long[] since;
    private final Map<String, Integer> ruleIndex = new HashMap<>();

    CoverageRecorder(Tree tree, IoModel io) {
        List<String> nodes = new ArrayList<>();
        root = tree.root();
        walk(root, root.path(), nodes);
        List<String> variants = new ArrayList<>();
        List<Integer> firsts = new ArrayList<>();
        for (VariationPoint vp : io.varpoints()) {
            if (vp.kind().equals("enum")) {
                enumIndex.put(vp.name(), firsts.size());
                firsts.add(variants.size());
                vp.values().forEach(v -> variants.add(vp.name() + "::" + v.asText()));
            }
        }
        first = firsts.stream().mapToInt(Integer::intValue).toArray();
        current = new int[first.length];
        Arrays.fill(current, -1);
        since = new long[first.length];
        List<String> rules = new ArrayList<>();
        JsonNode decided = io.decision() == null ? null : io.decision().path("rules");
        if (decided != null && decided.size() > 0) {
            decided.forEach(r -> rules.add(r.path("name").asText()));
        } else {
            io.rules().forEach(r -> rules.add(r.name()));
        }
        for (int i = 0; i < rules.size(); i++) {
            ruleIndex.putIfAbsent(rules.get(i), i);
        }
        counts = new Coverage(List.copyOf(nodes), List.copyOf(variants), List.copyOf(rules));
        lastMission = new long[nodes.size()];
        Arrays.fill(lastMission, -1);
    }

    /**
     * Depth first, as the tree draws: the executor's path, a sibling's position ({@code [k]}) added
     * where siblings share a name, so every node has its own line.
     */
    private void walk(Node node, String path, List<String> into) {
        nodeIndex.put(node, into.size());
        into.add(path);
        List<Node> children = node.children();
        Map<String, Integer> seen = new HashMap<>();
        for (Node c : children) {
            seen.merge(c.name(), 1, Integer::sum);
        }
        Map<String, Integer> k = new HashMap<>();
        for (Node c : children) {
            int n = k.merge(c.name(), 1, Integer::sum) - 1;
            walk(c, path + "/" + c.name() + (seen.get(c.name()) > 1 ? "[" + n + "]" : ""), into);
        }
    }

    /** Before each tick of the root: an idle root starts a new mission. */
    void beforeRootTick() {
        if (root.status() == NodeStatus.IDLE) {
            counts.missions++;
        }
    }

    @Override
    public void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        Integer i = nodeIndex.get(node);
        if (i == null) {
            return;
        }
        if (from != NodeStatus.RUNNING && to != NodeStatus.IDLE) { // idle or finished, ticked again: an execution
            counts.ticked[i]++;
            if (lastMission[i] != counts.missions) {
                lastMission[i] = counts.missions;
                counts.missionsWith[i]++;
            }
        }
        if (to == NodeStatus.SUCCESS) {
            counts.succeeded[i]++;
        } else if (to == NodeStatus.FAILURE) {
            counts.failed[i]++;
        }
    }

    /** A value reaches varpoint {@code vp} at {@code now}: the value in force until then is credited its time. */
    void varpoint(VariationPoint vp, JsonNode value, long now) {
        Integer k = enumIndex.get(vp.name());
        if (k == null) {
            return;
        }
        int v = vp.indexOf(value);
        hold(k, now);
        current[k] = v < 0 ? -1 : first[k] + v;
    }

    /** A solved decision and the rules it says applied ({@code [{"rule": name, ...}]}, absent without a decision section). */
    void decision(JsonNode appliedRules) {
        counts.decisions++;
        for (JsonNode r : appliedRules) {
            Integer i = ruleIndex.get(r.path("rule").asText());
            if (i != null) {
                counts.applied[i]++;
            }
        }
    }

    private void hold(int k, long now) {
        if (current[k] >= 0) {
            counts.heldMs[current[k]] += now - since[k];
        }
        since[k] = now;
    }

    /** The run's coverage at its end. */
    Coverage finish(long durationMs) {
        for (int k = 0; k < first.length; k++) {
            hold(k, durationMs);
        }
        counts.durationMs = durationMs;
        return counts;
    }
}
