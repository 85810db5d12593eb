package org.miron.runtime.sim;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.CompletableFuture;
import org.miron.executor.Blackboard;
import org.miron.executor.scripting.ScriptScope;
import org.miron.executor.scripting.ScriptValues;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;
import org.miron.runtime.sim.WorldModel.Outcome;
import org.miron.runtime.sim.WorldModel.Process;
import org.miron.runtime.sim.WorldModel.SkillModel;
import org.miron.runtime.sim.WorldModel.StateVar;

/**
 * A world being simulated: its state on a blackboard the expressions read and write, the skills
 * running in it, its processes, and the events of the current instant. Time is given (ms) and only
 * moves forward; rates of change hold between two instants (evaluated at the first). Single-threaded,
 * and every random draw comes from one seeded generator, so a run is a function of its seed.
 */
public final class World {
    /** A skill running in the world. */
    private static final class Run {
        final SkillModel model;
        final String name;
        final Map<String, Object> inputs;
        final CompletableFuture<SkillResult> result = new CompletableFuture<>();
        long end;
        /** Share of the skill done at {@code timedAt}, when its end was last computed. */
        double done;
        long timedAt;
        String targetPlace;
        double tx;
        double ty;
        double distance;
        boolean failed;

        Run(SkillModel model, String name, Map<String, Object> inputs) {
            this.model = model;
            this.name = name;
            this.inputs = inputs;
        }
    }

    private final WorldModel model;
    private final SplittableRandom random;
    private final Blackboard board = Blackboard.create();
    private final ScriptScope scope = new ScriptScope(board, Map.of());
    private final List<Run> runs = new ArrayList<>();
    private final long[] nextOccurrence;
    private final List<String> events = new ArrayList<>();
    private final List<String> problems = new ArrayList<>();
    private long now;
    private double x;
    private double y;
    private String place = "";
    private String lastSkill = "";
    private long shownTime = -1;
    private String shownSkill;
    private String shownPlace;

    public World(WorldModel model, long seed) {
        this.model = model;
        this.random = new SplittableRandom(seed);
        this.nextOccurrence = new long[model.processes().size()];
        for (StateVar v : model.state()) {
            board.set(v.name(), v.initial());
        }
        model.parameters().forEach(board::set);
        if (model.start() != null) {
            WorldModel.Place p = model.places().get(model.start());
            x = p.x();
            y = p.y();
            place = p.name();
        }
    }

    /** Arms the processes at time {@code t} (the run's start). */
    public void start(long t) {
        now = t;
        for (int i = 0; i < nextOccurrence.length; i++) {
            Process p = model.processes().get(i);
            nextOccurrence[i] = p.everyMs() != null ? t + p.everyMs() : Long.MAX_VALUE;
        }
        drawOccurrences();
    }

    public long now() {
        return now;
    }

    // ---- reading the state

    /** Evaluates an expression of the world now (a fresh {@code random} for it). */
    public Object eval(Expr e) {
        // The built-ins are written only when they change: blackboard writes are the cost of a run.
        if (now != shownTime) {
            board.set("time", now / 1000.0);
            shownTime = now;
        }
        String skill = skill();
        if (!skill.equals(shownSkill)) {
            board.set("skill", skill);
            shownSkill = skill;
        }
        if (!place.equals(shownPlace)) {
            board.set("place", place);
            shownPlace = place;
        }
        if (e.reads().contains("random")) {
            board.set("random", random.nextDouble());
        }
        return e.run(scope);
    }

    public double number(Expr e) {
        return ScriptValues.toDouble(eval(e));
    }

    public boolean bool(Expr e) {
        return ScriptValues.toBoolean(eval(e));
    }

    /** A state variable's or parameter's value as its declared type: Double, Boolean or String. */
    public Object value(String name) {
        return board.get(name).orElse(null);
    }

    /** The name of the skill running (the latest pushed), or "". */
    public String skill() {
        return runs.isEmpty() ? "" : runs.get(runs.size() - 1).name;
    }

    public String lastSkill() {
        return lastSkill;
    }

    /** A component parameter changed by the adaptation (change-parameter), as a number or boolean. */
    public void setParameter(String name, Object value) {
        if (model.parameters().containsKey(name) && !same(value(name), value)) {
            board.set(name, value);
            retime();
        }
    }

    private static boolean same(Object a, Object b) {
        return a instanceof Number x && b instanceof Number y ? x.doubleValue() == y.doubleValue() : java.util.Objects.equals(a, b);
    }

    // A parameter changed while skills run (the robot slowed down mid-move): each running skill's
    // duration is evaluated again, and the share still to do takes that share of the new
    // duration. What is done stays done; a skill whose duration does not read the parameter ends
    // when it would have.
    private void retime() {
        for (Run r : runs) {
            if (r.failed || r.end <= now || r.end <= r.timedAt) {
                continue;
            }
            double done = r.done + (1 - r.done) * (now - r.timedAt) / (double) (r.end - r.timedAt);
            setInputs(r);
            double seconds = number(r.model.duration());
            if (!Double.isFinite(seconds) || seconds <= 0) {
                continue;
            }
            r.done = done;
            r.timedAt = now;
            r.end = now + Math.round((1 - done) * seconds * 1000);
        }
    }

    /** Events that occurred since the last call, in order. */
    public List<String> takeEvents() {
        List<String> out = List.copyOf(events);
        events.clear();
        return out;
    }

    /** Things the world could not do (a skill sent to a place it does not know): said once each. */
    public List<String> problems() {
        return problems;
    }

    // ---- time

    /** The next instant something happens by itself: a skill ends or a process occurs. */
    public long nextEvent() {
        long next = Long.MAX_VALUE;
        for (Run r : runs) {
            next = Math.min(next, r.end);
        }
        for (long t : nextOccurrence) {
            next = Math.min(next, t);
        }
        return next;
    }

    /** Lets the rates of change act until {@code t} (ms), at the rates of now. */
    public void advance(long t) {
        if (t <= now) {
            return;
        }
        double dt = (t - now) / 1000.0;
        List<Map.Entry<String, Double>> changes = new ArrayList<>();
        for (Run r : runs) {
            if (!r.model.perSecond().isEmpty()) {
                setInputs(r);
                r.model.perSecond().forEach((name, e) -> changes.add(Map.entry(name, number(e) * dt)));
            }
        }
        for (Process p : model.processes()) {
            if (!p.perSecond().isEmpty() && (p.whileExpr() == null || bool(p.whileExpr()))) {
                p.perSecond().forEach((name, e) -> changes.add(Map.entry(name, number(e) * dt)));
            }
        }
        for (Map.Entry<String, Double> c : changes) {
            board.set(c.getKey(), ScriptValues.toDouble(ScriptValues.of(board.get(c.getKey()).orElse(0.0))) + c.getValue());
        }
        now = t;
        clamp();
    }

    /** Ends the skills due now, runs the processes due now, stops skills whose requirement fails. */
    public void fire() {
        for (Run r : List.copyOf(runs)) {
            if (r.end <= now) {
                finish(r);
            }
        }
        for (int i = 0; i < nextOccurrence.length; i++) {
            if (nextOccurrence[i] <= now) {
                Process p = model.processes().get(i);
                if (p.everyMs() != null) {
                    nextOccurrence[i] += p.everyMs();
                }
                if (p.whileExpr() == null || bool(p.whileExpr())) {
                    occur(p);
                }
            }
        }
        for (Run r : List.copyOf(runs)) {
            if (r.model.requires() != null && !requirementHolds(r)) {
                fail(r);
            }
        }
        drawOccurrences();
        clamp();
    }

    private void occur(Process p) {
        if (p.effect() != null) {
            eval(p.effect());
        }
        events.addAll(p.events());
        if (p.abortSkill()) {
            List.copyOf(runs).forEach(this::fail);
        }
    }

    /** Random processes: the next occurrence at the current rate (memoryless, so drawing again at every instant is exact). */
    private void drawOccurrences() {
        for (int i = 0; i < nextOccurrence.length; i++) {
            Process p = model.processes().get(i);
            if (p.rate() == null) {
                continue;
            }
            double rate = p.whileExpr() == null || bool(p.whileExpr()) ? number(p.rate()) : 0;
            nextOccurrence[i] = rate > 0 && Double.isFinite(rate)
                    ? now + Math.max(1, Math.round(-Math.log(1 - random.nextDouble()) / rate * 1000)) : Long.MAX_VALUE;
        }
    }

    private void clamp() {
        for (StateVar v : model.state()) {
            if (v.min() != null || v.max() != null) {
                double d = ScriptValues.toDouble(ScriptValues.of(board.get(v.name()).orElse(0.0)));
                double c = Math.max(v.min() == null ? d : v.min(), Math.min(v.max() == null ? d : v.max(), d));
                if (c != d) {
                    board.set(v.name(), c);
                }
            }
        }
    }

    // ---- skills

    /** Starts a skill pushed by the behaviour tree now; its result completes at a later {@link #fire}. */
    public SkillHandle push(SkillRequest request) {
        SkillModel m = model.skills().getOrDefault(request.name(), model.anySkill());
        Run r = new Run(m, request.name(), request.inAttributes());
        lastSkill = request.name();
        r.end = now;
        if (m == null) {
            problem("skill " + request.name() + " is not in the world: it fails");
            r.failed = true;
            runs.add(r);
            return handle(r);
        }
        runs.add(r);
        if (m.target() != null && !locate(r)) {
            r.failed = true;
            return handle(r);
        }
        setInputs(r);
        if (m.requires() != null && !requirementHolds(r)) {
            r.failed = true;
            return handle(r);
        }
        if (m.start() != null) {
            eval(m.start());
        }
        if (m.target() != null) {
            place = "";
        }
        double seconds = number(m.duration());
        r.timedAt = now;
        r.end = now + (Double.isFinite(seconds) && seconds > 0 ? Math.round(seconds * 1000) : 0);
        return handle(r);
    }

    private SkillHandle handle(Run r) {
        return SkillHandle.of(r.result, () -> {
            if (runs.remove(r)) {
                r.result.complete(SkillResult.of(SkillResult.Outcome.ABORT));
            }
        });
    }

    private boolean requirementHolds(Run r) {
        setInputs(r);
        return bool(r.model.requires());
    }

    /** Where a moving skill goes, and how far: a path length of the world, else the straight line. */
    private boolean locate(Run r) {
        var t = r.model.target();
        if (t.place() != null) {
            String name = String.valueOf(r.inputs.get(t.place()));
            WorldModel.Place p = model.places().get(name);
            if (p == null) {
                problem("skill " + r.name + " sent to '" + name + "', which is no place of the world: it fails");
                return false;
            }
            r.targetPlace = name;
            r.tx = p.x();
            r.ty = p.y();
        } else {
            try {
                r.tx = ScriptValues.toDouble(ScriptValues.of(r.inputs.get(t.x())));
                r.ty = ScriptValues.toDouble(ScriptValues.of(r.inputs.get(t.y())));
            } catch (RuntimeException e) {
                problem("skill " + r.name + " has no numeric " + t.x() + "/" + t.y() + ": it fails");
                return false;
            }
            r.targetPlace = "";
            for (WorldModel.Place p : model.places().values()) {
                if (Math.hypot(p.x() - r.tx, p.y() - r.ty) < 0.5) {
                    r.targetPlace = p.name();
                    break;
                }
            }
        }
        Double path = model.distances().get(place + "|" + r.targetPlace);
        r.distance = path != null ? path : Math.hypot(r.tx - x, r.ty - y);
        return true;
    }

    private void setInputs(Run r) {
        r.inputs.forEach((k, v) -> {
            if (!model.parameters().containsKey(k) && model.state().stream().noneMatch(s -> s.name().equals(k))) {
                board.set(k, v instanceof Number n ? (Object) n.doubleValue() : v);
            }
        });
        if (r.model.target() != null) {
            board.set("distance", r.distance);
        }
    }

    private void finish(Run r) {
        runs.remove(r);
        if (r.failed) {
            r.result.complete(SkillResult.of(SkillResult.Outcome.ERROR));
            return;
        }
        setInputs(r);
        Outcome drawn = null;
        for (Outcome o : r.model.outcomes()) {
            Object p = o.probability() == null ? 1.0 : eval(o.probability());
            double chance = ScriptValues.toDouble(p);
            if (random.nextDouble() < chance) {
                drawn = o;
                break;
            }
        }
        boolean success = drawn == null || drawn.success();
        if (success) {
            if (r.model.target() != null) {
                x = r.tx;
                y = r.ty;
                place = r.targetPlace;
            }
            if (r.model.end() != null) {
                eval(r.model.end());
            }
            events.addAll(r.model.events());
        }
        if (drawn != null) {
            if (drawn.effect() != null) {
                eval(drawn.effect());
            }
            events.addAll(drawn.events());
        }
        r.result.complete(SkillResult.of(success ? SkillResult.Outcome.SUCCESS : SkillResult.Outcome.ERROR));
    }

    /** Ends a running skill with ERROR now (a failed requirement, an emergency stop), without its end effects. */
    private void fail(Run r) {
        if (runs.remove(r)) {
            r.result.complete(SkillResult.of(SkillResult.Outcome.ERROR));
        }
    }

    /** Records something the world or the tree could not do, once. */
    void problem(String message) {
        if (!problems.contains(message)) {
            problems.add(message);
        }
    }
}
