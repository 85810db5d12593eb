package org.miron.runtime.roqme.expr;

import java.util.List;
import java.util.Map;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * A runtime model ready to run (for one provider: see {@link #claim}): slots, the computed slots in
 * dependency order, the timers (the declared ones, then one per {@code schedule("...")} call in a
 * pattern), the compiled observations and the beliefs' reasoner parameters.
 */
public record CompiledModel(RoqmeModel model, int slots, Map<String, Symbol> symbols, List<Computed> computed,
        List<RoqmeModel.Timer> timers, List<Window> windows, List<CompiledObservation> observations, List<CompiledBelief> beliefs,
        Map<Integer, Object> initialValues, Map<String, String> params, java.util.concurrent.atomic.AtomicBoolean claimed) {

    /**
     * Patterns and windows keep state, so a compiled model serves one provider: the first caller gets
     * this one, any later caller (a restarted provider, a second replay) a fresh compilation.
     */
    public CompiledModel claim() {
        if (claimed.compareAndSet(false, true)) {
            return this;
        }
        try {
            CompiledModel m = Compiler.compile(model, new java.util.HashMap<>(params));
            m.claimed.set(true);
            return m;
        } catch (org.miron.runtime.roqme.model.ModelException e) {
            throw new IllegalStateException("compiled once, refused now: " + e.getMessage(), e);
        }
    }

    /** A derived context or var ({@code expr}), or a window ({@code window}); {@code deps} are the slots it reads. */
    public record Computed(int slot, ValueNode expr, Window window, int[] deps) {
    }

    public record CompiledObservation(int index, String id, RoqmeModel.Observation decl, EventNode pattern, int[] deps,
            List<CompiledAction> actions) {
    }

    /**
     * {@code kind}: reinforces/undermines ({@code ratio} r, {@code survivalMs} resolved), clears,
     * sets ({@code target} var slot, {@code value}), starts/stops/resumes ({@code target} timer index).
     */
    public record CompiledAction(Kind kind, int target, double ratio, long survivalMs, ValueNode value) {
        /** The action kinds; an enum so that a tick does not compare strings. */
        public enum Kind {
            REINFORCES, UNDERMINES, CLEARS, SETS, STARTS, STOPS, RESUMES;

            static Kind of(String text) {
                return valueOf(text.toUpperCase(java.util.Locale.ROOT));
            }
        }
    }

    /** A property or beliefvar; {@code expr} for a property defined by an expression of other beliefs. */
    public record CompiledBelief(int index, int slot, RoqmeModel.Belief decl, ValueNode expr) {
    }
}
