package org.miron.runtime.roqme;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.logging.Logger;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledAction;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledBelief;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledObservation;
import org.miron.runtime.roqme.expr.CompiledModel.Computed;
import org.miron.runtime.roqme.expr.Store;
import org.miron.runtime.roqme.expr.Window;
import org.miron.runtime.roqme.reasoner.Reasoner;

/**
 * The QoS Metrics Provider on a clock it is given (ms): the same code serves the live service and
 * the replay. Single-threaded. Inputs, timer firings and window drops are <em>steps</em>: the
 * updated slots' computed dependents are recomputed in dependency order, then the observations that
 * read an updated slot are evaluated; a firing runs {@code sets} (a follow-up step at the same
 * time) and timer actions at once and is collected for the next tick, where the reasoner turns the
 * set of fired observations into evidence (docs/roqme-provider.md).
 */
public final class Provider {
    private static final Logger LOG = Logger.getLogger(Provider.class.getName());
    private static final int MAX_CASCADE = 16;

    /** What a tick produced: every property's estimate (declaration order) and the observations fired. */
    public record Tick(long k, long timeMs, double[] estimates, List<String> fired) {
    }

    /** Told of every firing at the time it happens (the live service publishes it at once). */
    public interface FireListener {
        void fired(CompiledObservation o, long time);
    }

    private record Due(long time, long seq, int kind, int index, int generation) {
    }

    private final CompiledModel model;
    private final long periodMs;
    private final long startMs;
    private final Store store;
    private final Computed[] computed;
    private final int[][] computedDependents; // slot -> positions in computed
    private final int[][] observationDependents; // slot -> observation indexes
    private final TimerState[] timers;
    private final int[] timerBySlot;
    private final Window[] windows;
    private final long[] windowDue;
    private final Reasoner reasoner;
    private final int[] beliefIndexBySlot;
    private final double[] beliefEstimates;
    private final int propertyCount;
    private final boolean[] isProperty; // by belief index
    private final PriorityQueue<Due> queue = new PriorityQueue<>((a, b) -> a.time != b.time
            ? Long.compare(a.time, b.time) : Long.compare(a.seq, b.seq));
    private final BitSet pendingComputed = new BitSet();
    private final BitSet pendingObservations = new BitSet();
    private final BitSet firedThisTick = new BitSet();
    private final int[] updatedList;
    private int updatedCount;
    private long seq;
    private long tick;
    private long samples;
    private long firings;
    private FireListener listener = (o, t) -> { };

    public Provider(CompiledModel model, long periodMs, long startMs) {
        if (periodMs <= 0) {
            throw new IllegalArgumentException("the period must be positive, got " + periodMs);
        }
        model = model.claim();
        this.model = model;
        this.periodMs = periodMs;
        this.startMs = startMs;
        int n = model.slots();
        store = new Store(n);
        updatedList = new int[n + 1];
        computed = model.computed().toArray(new Computed[0]);
        List<List<Integer>> cd = lists(n);
        for (int i = 0; i < computed.length; i++) {
            for (int d : computed[i].deps()) {
                cd.get(d).add(i);
            }
        }
        computedDependents = arrays(cd);
        List<List<Integer>> od = lists(n);
        for (CompiledObservation o : model.observations()) {
            for (int d : o.deps()) {
                od.get(d).add(o.index());
            }
        }
        observationDependents = arrays(od);
        timers = new TimerState[model.timers().size()];
        timerBySlot = new int[n];
        for (int i = 0; i < timers.length; i++) {
            var t = model.timers().get(i);
            timers[i] = new TimerState(t, model.symbols().get(t.id()).slot());
            timerBySlot[timers[i].slot] = i;
        }
        windows = model.windows().toArray(new Window[0]);
        windowDue = new long[windows.length];
        java.util.Arrays.fill(windowDue, -1);
        beliefIndexBySlot = new int[n];
        double[] refs = new double[model.beliefs().size()];
        beliefEstimates = new double[refs.length];
        for (CompiledBelief b : model.beliefs()) {
            refs[b.index()] = b.decl().ref();
            beliefEstimates[b.index()] = b.decl().ref();
            beliefIndexBySlot[b.slot()] = b.index();
        }
        reasoner = new Reasoner(periodMs, refs);
        propertyCount = (int) model.beliefs().stream().filter(b -> b.decl().isProperty()).count();
        isProperty = new boolean[refs.length];
        for (CompiledBelief b : model.beliefs()) {
            isProperty[b.index()] = b.decl().isProperty();
        }
    }

    private static List<List<Integer>> lists(int n) {
        List<List<Integer>> l = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            l.add(new ArrayList<>());
        }
        return l;
    }

    private static int[][] arrays(List<List<Integer>> l) {
        int[][] a = new int[l.size()][];
        for (int i = 0; i < a.length; i++) {
            a[i] = l.get(i).stream().mapToInt(Integer::intValue).toArray();
        }
        return a;
    }

    public CompiledModel model() {
        return model;
    }

    public long startMs() {
        return startMs;
    }

    public long periodMs() {
        return periodMs;
    }

    /** The next tick's number and time. */
    public long nextTick() {
        return tick + 1;
    }

    public long nextTickTime() {
        return startMs + (tick + 1) * periodMs;
    }

    public long samples() {
        return samples;
    }

    public long firings() {
        return firings;
    }

    public Provider onFire(FireListener l) {
        this.listener = l;
        return this;
    }

    /** Sets params, computes vars and derived contexts, arms the timers that are not paused. */
    public Provider start() {
        store.newStep(startMs);
        updatedCount = 0;
        for (Map.Entry<Integer, Object> p : model.initialValues().entrySet()) {
            store.set(p.getKey(), p.getValue());
            updated(p.getKey());
        }
        for (CompiledBelief b : model.beliefs()) {
            store.set(b.slot(), b.decl().ref());
            updated(b.slot());
        }
        for (Window w : windows) {
            w.init(store);
        }
        pendingComputed.set(0, computed.length);
        pendingObservations.set(0, model.observations().size());
        propagate(0);
        for (TimerState t : timers) {
            if (!t.decl.paused()) {
                t.start(startMs);
                schedule(t);
            }
        }
        return this;
    }

    /** Runs every timer firing and window drop due at or before {@code time}, in time order. */
    public void advanceTo(long time) {
        Due d;
        while ((d = queue.peek()) != null && d.time <= time) {
            queue.poll();
            if (d.kind == 0) {
                TimerState t = timers[d.index];
                if (d.generation != t.generation) {
                    continue; // re-armed or stopped since
                }
                t.fired(d.time);
                schedule(t);
                beginStep(d.time);
                store.set(t.slot, Boolean.TRUE);
                updated(t.slot);
                propagate(0);
            } else {
                Window w = windows[d.index];
                if (windowDue[d.index] != d.time) {
                    continue;
                }
                windowDue[d.index] = -1;
                beginStep(d.time);
                if (w.expire(store)) {
                    updated(w.slot());
                }
                propagate(0);
                scheduleExpiry(d.index);
            }
        }
    }

    /** A context sample (already checked against its type) at {@code time}. */
    public void input(int slot, Object value, long time) {
        advanceTo(time);
        samples++;
        beginStep(time);
        store.set(slot, value);
        updated(slot);
        propagate(0);
    }

    /**
     * The next tick: runs what is due up to its time, adds the evidence of the observations fired
     * since the previous tick (a set: each counts once) and computes every belief.
     */
    public Tick tick() {
        long k = ++tick;
        long time = startMs + k * periodMs;
        advanceTo(time);
        List<String> fired = new ArrayList<>();
        for (int i = firedThisTick.nextSetBit(0); i >= 0; i = firedThisTick.nextSetBit(i + 1)) {
            CompiledObservation o = model.observations().get(i);
            fired.add(o.id());
            for (CompiledAction a : o.actions()) {
                switch (a.kind()) {
                    case REINFORCES, UNDERMINES -> reasoner.add(beliefIndexBySlot[a.target()], a.ratio(), a.survivalMs(), k);
                    case CLEARS -> reasoner.clear(beliefIndexBySlot[a.target()]);
                    default -> {
                    }
                }
            }
        }
        firedThisTick.clear();
        beginStep(time);
        for (CompiledBelief b : model.beliefs()) {
            double v;
            if (b.expr() == null) {
                v = reasoner.estimate(b.index(), k);
            } else { // a property defined by an expression: unknown keeps its reference
                Object o = b.expr().eval(store);
                v = o instanceof Double d && !d.isNaN() ? Math.max(0, Math.min(1, d)) : b.decl().ref();
            }
            if (v != beliefEstimates[b.index()]) {
                beliefEstimates[b.index()] = v;
                store.set(b.slot(), v);
                updated(b.slot());
            }
        }
        propagate(0); // observations reading beliefs: their firings count at the next tick
        double[] props = new double[propertyCount];
        int i = 0;
        for (int b = 0; b < isProperty.length; b++) {
            if (isProperty[b]) {
                props[i++] = beliefEstimates[b];
            }
        }
        return new Tick(k, time, props, fired);
    }

    /** The live evidence of every belief by id, aged as of the last tick (for {@code --state}). */
    public Map<String, List<Reasoner.Piece>> evidence() {
        Map<String, List<Reasoner.Piece>> out = new java.util.LinkedHashMap<>();
        for (CompiledBelief b : model.beliefs()) {
            out.put(b.decl().id(), reasoner.pieces(b.index(), tick));
        }
        return out;
    }

    /**
     * Restores saved evidence, {@code elapsedMs} older than when it was saved (it kept decaying
     * while the provider was down); beliefs the model no longer has are skipped. Call after
     * {@link #start} and before the first tick.
     */
    public void restore(Map<String, List<Reasoner.Piece>> saved, long elapsedMs) {
        for (CompiledBelief b : model.beliefs()) {
            for (Reasoner.Piece p : saved.getOrDefault(b.decl().id(), List.of())) {
                reasoner.restore(b.index(), new Reasoner.Piece(p.r(), p.survivalMs(), p.ageMs() + elapsedMs), tick);
            }
        }
    }

    /** The current estimate of belief {@code index} (declaration order of beliefs). */
    public double estimate(int index) {
        return beliefEstimates[index];
    }

    /** The current value of a declaration by id (null: unknown). */
    public Object value(String id) {
        var s = model.symbols().get(id);
        return s == null ? null : store.get(s.slot());
    }

    /** Time of the next timer firing or window drop, or Long.MAX_VALUE. */
    public long nextDue() {
        Due d = queue.peek();
        return d == null ? Long.MAX_VALUE : d.time;
    }

    // ---- steps

    private void beginStep(long time) {
        store.newStep(time);
        updatedCount = 0;
    }

    private void updated(int slot) {
        if (updatedCount < updatedList.length) {
            updatedList[updatedCount++] = slot;
        }
        for (int c : computedDependents[slot]) {
            pendingComputed.set(c);
        }
    }

    private void propagate(int depth) {
        for (int i = pendingComputed.nextSetBit(0); i >= 0; i = pendingComputed.nextSetBit(i + 1)) {
            pendingComputed.clear(i);
            Computed c = computed[i];
            if (c.window() != null) {
                c.window().sample(store);
                if (store.updated(c.slot())) {
                    updated(c.slot());
                    scheduleExpiry(c.window().index());
                }
            } else if (c.expr() != null) {
                store.set(c.slot(), c.expr().eval(store));
                updated(c.slot());
            }
        }
        for (int u = 0; u < updatedCount; u++) {
            for (int o : observationDependents[updatedList[u]]) {
                pendingObservations.set(o);
            }
        }
        List<CompiledAction> sets = null;
        for (int i = pendingObservations.nextSetBit(0); i >= 0; i = pendingObservations.nextSetBit(i + 1)) {
            pendingObservations.clear(i);
            CompiledObservation o = model.observations().get(i);
            if (!o.pattern().occurs(store)) {
                continue;
            }
            firings++;
            firedThisTick.set(i);
            listener.fired(o, store.now());
            for (CompiledAction a : o.actions()) {
                switch (a.kind()) {
                    case SETS -> {
                        if (sets == null) {
                            sets = new ArrayList<>();
                        }
                        sets.add(a);
                    }
                    case STARTS -> schedule(timers[timerBySlot[a.target()]], t -> t.start(store.now()));
                    case STOPS -> schedule(timers[timerBySlot[a.target()]], t -> t.stop(store.now()));
                    case RESUMES -> schedule(timers[timerBySlot[a.target()]], t -> t.resume(store.now()));
                    default -> {
                    }
                }
            }
        }
        if (sets != null) {
            if (depth >= MAX_CASCADE) {
                LOG.warning("roqme: more than " + MAX_CASCADE + " cascading 'sets' at one time; the rest is dropped");
                return;
            }
            Object[] values = new Object[sets.size()];
            for (int i = 0; i < values.length; i++) {
                values[i] = sets.get(i).value().eval(store);
            }
            beginStep(store.now());
            for (int i = 0; i < values.length; i++) {
                store.set(sets.get(i).target(), values[i]);
                updated(sets.get(i).target());
            }
            propagate(depth + 1);
        }
    }

    private void schedule(TimerState t, java.util.function.Consumer<TimerState> change) {
        change.accept(t);
        schedule(t);
    }

    private void schedule(TimerState t) {
        if (t.next() >= 0) {
            queue.add(new Due(t.next(), seq++, 0, timerBySlot[t.slot], t.generation));
        }
    }

    private void scheduleExpiry(int w) {
        long due = windows[w].nextExpiry();
        if (due >= 0 && due != windowDue[w]) {
            windowDue[w] = due;
            queue.add(new Due(due, seq++, 1, w, 0));
        }
    }
}
