package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Logger;
import org.miron.runtime.Json;

/**
 * What the engine does with one solve, without the bus or a thread: checks the result, decides
 * which varpoints change (and which a decision holds back), and writes the decision-log entry. The
 * live {@link Engine} sends the changes on the bus; the simulator applies them to its executor and
 * world on a virtual clock. One caller thread at a time.
 */
public final class Decider {
    private static final Logger LOG = Logger.getLogger(Decider.class.getName());

    /** A varpoint whose applied value changed, and the value to send. */
    public record Change(VariationPoint varpoint, JsonNode value) {
    }

    /** One decision: its log entry (also the {@code miron.decision} body) and what changed. */
    public record Outcome(ObjectNode entry, List<Change> changes, SolveResult result) {
    }

    private final IoModel model;
    private final SolverBackend backend;
    private final InputState state;
    private final EngineStatus status;
    private final Map<String, Integer> applied = new LinkedHashMap<>();
    /** Varpoints a decision has set: from then on the model's tie-break decides. */
    private final Set<String> sent = new java.util.HashSet<>();
    private final RuleActivity activity; // null without a decision section
    private final DecisionExplainer explainer; // null with activity
    private volatile Map<String, Object> appliedValues = Map.of();
    private long seq;

    public Decider(IoModel model, SolverBackend backend, InputState state, EngineStatus status) {
        this.model = model;
        this.backend = backend;
        this.state = state;
        this.status = status;
        this.activity = activity(model);
        this.explainer = activity == null ? null : new DecisionExplainer(model, activity);
        Map<String, Object> initial = new LinkedHashMap<>();
        for (VariationPoint vp : model.varpoints()) {
            // The robot starts with it: applied before any decision. Not a BT port's: the woven tree
            // reads it from a blackboard key that only a decision writes, so the first one sends it.
            if (vp.initial() != null && !vp.bindingType().equals("btport")) {
                applied.put(vp.name(), vp.initial());
                initial.put(vp.name(), vp.values().get(vp.initial()));
            }
        }
        appliedValues = initial;
    }

    /** Rule activity needs the decision section; without it every decision is sent as before. */
    private static RuleActivity activity(IoModel model) {
        if (model.decision() == null) {
            return null;
        }
        try {
            return new RuleActivity(model);
        } catch (IllegalArgumentException e) {
            LOG.warning("decision section unusable for explanations: " + e.getMessage());
            return null;
        }
    }

    /** Solves on a snapshot of the inputs and decides; {@code time} goes into the entry (ms). */
    public Outcome decide(InputState.Snapshot snap, long time) {
        return handle(backend.solve(snap.params()), snap, time);
    }

    /** The configuration in force: varpoint → value. */
    public Map<String, Object> applied() {
        return appliedValues;
    }

    public SolverBackend backend() {
        return backend;
    }

    Outcome handle(SolveResult r, InputState.Snapshot snap, long time) {
        if (r.solved()) {
            String bad = outOfRange(r);
            if (bad != null) {
                r = SolveResult.failed(SolveResult.Status.ERROR, bad, r.millis());
            }
        }
        status.solveOutcome(r);
        backend.counters().forEach(status::set);
        ObjectNode entry = Json.object();
        entry.put("time", time);
        entry.put("model", model.model());
        entry.put("backend", backend.name());
        entry.put("solveMs", r.millis());
        entry.put("outcome", r.status().name());
        entry.set("inputs", inputs(snap.params()));
        List<Change> changes = List.of();
        if (r.solved()) {
            changes = apply(r, snap, entry);
        } else {
            entry.put("message", r.message());
            LOG.warning("solve failed (" + r.status() + "), keeping the last configuration: " + r.message());
        }
        return new Outcome(entry, changes, r);
    }

    /**
     * The solve's parameters as logged and published; a boolean varpoint's indices shown as its
     * values (false/true, null before the first decision), so the 0/1 of the .mzn stays inside.
     */
    private ObjectNode inputs(Map<String, Object> params) {
        ObjectNode inputs = Json.MAPPER.valueToTree(params);
        for (VariationPoint vp : model.varpoints()) {
            if (vp.isBoolean()) {
                for (String param : List.of(vp.inputValue(), vp.current())) {
                    if (params.get(param) instanceof Integer index) {
                        inputs.set(param, vp.valueAt(index));
                    }
                }
            }
        }
        return inputs;
    }

    private String outOfRange(SolveResult r) {
        for (VariationPoint vp : model.varpoints()) {
            int idx = r.decisions().get(vp.decision());
            if (idx < 0 || idx >= vp.values().size()) {
                return vp.decision() + " = " + idx + " is not an index of " + vp.name() + "'s values";
            }
        }
        return null;
    }

    /**
     * Applies a decision: returns what changed, except for parameters (varpoints not woven into the
     * tree as variants, whose preset the executor expects at start-up) no decision has set yet that
     * nothing asks to change (no impact, no applicable rule, no override): they keep their initial
     * value, or stay unset ({@code null} in the decision). A BT port's initial value is sent by the
     * first decision (the tree's blackboard has nothing before). Once a rule has set one, the model's
     * tie-break decides when the rule lets go: back to the preset (or the initial value), else the
     * current value stays.
     */
    private List<Change> apply(SolveResult r, InputState.Snapshot snap, ObjectNode entry) {
        seq++;
        ArrayNode changed = Json.MAPPER.createArrayNode();
        ArrayNode held = Json.MAPPER.createArrayNode();
        ObjectNode decisions = Json.object();
        Map<String, Object> values = new LinkedHashMap<>();
        RuleActivity.Activity act = activity == null ? null
                : activity.evaluate(snap.params(), r.decisions(), r.dropped());
        List<Change> changes = new ArrayList<>();
        for (int v = 0; v < model.varpoints().size(); v++) {
            VariationPoint vp = model.varpoints().get(v);
            if (act != null && !act.asked()[v] && !sent.contains(vp.name()) && !vp.bindingType().equals("bt")
                    && !(vp.bindingType().equals("btport") && vp.initial() != null)) {
                held.add(vp.name());
                Integer kept = applied.get(vp.name());
                decisions.set(vp.name(), kept == null ? null : vp.values().get(kept));
                if (kept != null) {
                    values.put(vp.name(), vp.values().get(kept));
                }
                continue;
            }
            int idx = r.decisions().get(vp.decision());
            JsonNode value = vp.values().get(idx);
            decisions.set(vp.name(), value);
            values.put(vp.name(), value);
            Integer before = applied.put(vp.name(), idx);
            if (before == null || before != idx) {
                changed.add(vp.name());
                sent.add(vp.name());
                state.setCurrent(vp, idx);
                changes.add(new Change(vp, value));
            }
        }
        appliedValues = values;
        entry.put("seq", seq);
        entry.put("optimal", r.optimal());
        entry.set("dropped", Json.MAPPER.valueToTree(r.dropped()));
        entry.set("held", held);
        if (act != null) {
            entry.set("applied", explainer.applied(act));
            ObjectNode why = entry.putObject("why");
            for (Change c : changes) {
                why.set(c.varpoint().name(), explainer.explain(act, model.varpoints().indexOf(c.varpoint())));
            }
        }
        if (!r.dropped().isEmpty()) {
            status.count("droppedRules");
            LOG.info("rules dropped for higher ones: " + String.join(", ", r.dropped()));
        }
        entry.set("decisions", decisions);
        entry.set("changed", changed);
        return changes;
    }

    /** The sequence number of the last decision (the {@code seq} of its outputs). */
    public long seq() {
        return seq;
    }
}
