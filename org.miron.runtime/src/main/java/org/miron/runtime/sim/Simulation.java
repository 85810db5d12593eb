package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.TreeContext;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Decider;
import org.miron.runtime.engine.EngineStatus;
import org.miron.runtime.engine.InputSpec;
import org.miron.runtime.engine.InputState;
import org.miron.runtime.engine.NativeBackend;
import org.miron.runtime.engine.VariationPoint;
import org.miron.runtime.requirement.RequirementMessages;
import org.miron.runtime.requirement.RequirementMonitors;
import org.miron.runtime.requirement.RequirementResult;
import org.miron.runtime.roqme.ObservationMessage;
import org.miron.runtime.roqme.Provider;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.expr.Literals;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.WorldModel.Publication;

/**
 * One simulated run, broker-less on a virtual clock: the world, the RoQME provider, the engine's
 * decisions (native backend) and the behaviour tree share one time, which jumps to the next thing
 * that happens (a skill ends, a process occurs, a context is due, the provider ticks); nothing
 * sleeps. At each instant, in order: the world's skills and processes, the contexts it publishes,
 * the provider's tick, a decision if an input changed, one tick of the tree. A finished mission
 * starts again after the world's restart delay.
 */
public final class Simulation {
    /**
     * What a run measured; {@code timeline}: what it recorded for the report (empty unless asked);
     * {@code requirements}: each requirement's result over the run (empty when none is checked);
     * {@code coverage}: the nodes, variants and rules the run exercised.
     */
    public record Result(Map<String, Double> measures, List<String> problems, List<TimelineEvent> timeline,
            List<RequirementResult> requirements, Coverage coverage) {
    }

    private static final int MAX_STEPS_PER_INSTANT = 1000;

    private final Setup setup;
    private final Policy policy;
    private final long durationMs;
    private final long timelineMs;
    private final WorldDriver driver;
    private final World world;
    private final CompiledModel roqme;
    private final Provider provider;
    private final InputState inputs;
    private final List<RoqmeModel.Variable> derivedInputs = new java.util.ArrayList<>();
    private final Object[] lastDerived;
    private final Decider decider;
    private final VariantSource variants = new VariantSource();
    private final VariantSource blackboard = new VariantSource();
    private final Tree tree;
    private final Measures measures;
    private final CoverageRecorder coverage;
    private final Map<String, InputSpec> engineContexts = new HashMap<>();
    private final Map<String, InputSpec> engineMetrics = new HashMap<>();
    private final Map<String, RoqmeModel.Variable> contexts = new HashMap<>();
    private final List<TimelineEvent> timeline = new ArrayList<>();
    private final RequirementMonitors monitors;
    /** Derived contexts the requirements read: fed from the provider as the engine's are. */
    private final List<RoqmeModel.Variable> monitoredDerived = new ArrayList<>();
    private final Map<String, Object> lastMonitoredDerived = new HashMap<>();
    private long timelineFrom;
    private final double[] lastEstimates;
    private long now;
    private long seenVersion = -1;
    private long restartAt = -1;
    private int succeeded;
    private int failed;
    private int adaptations;
    private int solveFailures;
    private String lastSkill = "";
    private double realTime; // 0: virtual clock; else the wall clock, this many times faster

    public Simulation(Setup setup, Policy policy, long seed, long durationMs, long timelineMs) {
        this.setup = setup;
        this.policy = policy;
        this.durationMs = durationMs;
        this.timelineMs = timelineMs;
        this.driver = new WorldDriver(setup.world(), seed, this::publish);
        this.world = driver.world();
        this.roqme = compile(setup.roqme());
        this.provider = new Provider(roqme, 1000, 0);
        this.inputs = new InputState(setup.io());
        this.decider = policy.adaptive()
                ? new Decider(setup.io(), new NativeBackend(setup.io()), inputs, new EngineStatus(setup.io().model(), "native"))
                : null;
        TreeContext context = new TreeContext(() -> now);
        context.onProblem(world::problem); // e.g. a skill not pushed for a port nothing wrote: said once in the results
        this.tree = Setup.buildTree(setup.tree(), context, variants, new SkillActionStrategy(world::push));
        tree.feedBlackboardFrom(blackboard);
        coverage = new CoverageRecorder(tree, setup.io());
        tree.addListener(coverage);
        for (InputSpec in : setup.io().inputs()) {
            (in.isMetric() ? engineMetrics : engineContexts).put(in.name(), in);
        }
        for (RoqmeModel.Variable v : setup.roqme().contexts()) {
            contexts.put(v.name(), v);
            if (v.derived() != null && !v.derived().isNull() && engineContexts.containsKey(v.name())) {
                derivedInputs.add(v);
            }
        }
        lastDerived = new Object[derivedInputs.size()];
        monitors = setup.requirements() == null || setup.requirements().requirements().isEmpty() ? null
                : new RequirementMonitors(setup.requirements());
        if (monitors != null) {
            monitors.onEvent(e -> {
                if (inTimeline(e.timeMs())) {
                    timeline.add(new TimelineEvent(e.timeMs(), Topics.REQUIREMENT, RequirementMessages.event(e)));
                }
            });
            for (RoqmeModel.Variable v : setup.roqme().contexts()) {
                if (v.derived() != null && !v.derived().isNull() && monitors.contexts().contains(v.name())) {
                    monitoredDerived.add(v);
                }
            }
        }
        List<String> properties = setup.roqme().beliefs().stream().filter(RoqmeModel.Belief::isProperty)
                .map(RoqmeModel.Belief::name).toList();
        lastEstimates = setup.roqme().beliefs().stream().filter(RoqmeModel.Belief::isProperty)
                .mapToDouble(RoqmeModel.Belief::ref).toArray();
        measures = new Measures(setup.world().measures(), properties, lastEstimates);
        provider.onFire((o, t) -> {
            if (inTimeline(t)) {
                timeline.add(new TimelineEvent(t, Topics.OBSERVATION, observation(o.decl())));
            }
        });
    }

    /** Records the timeline over {@code [fromMs, toMs]} instead of from the start (a counterexample's surroundings). */
    public Simulation timelineWindow(long fromMs) {
        this.timelineFrom = fromMs;
        return this;
    }

    private boolean inTimeline(long t) {
        return t >= timelineFrom && t <= timelineMs;
    }

    /**
     * Runs on the wall clock instead ({@code speed} times faster than real time): each instant waits
     * until its time has come and happens at the time the clock then says, late by however long the
     * machine took. Only to compare with the virtual clock: the same decisions, in the same order.
     */
    public Simulation realTime(double speed) {
        this.realTime = speed;
        return this;
    }

    /** A fresh compilation for each run: patterns and windows keep state. */
    private static CompiledModel compile(RoqmeModel model) {
        try {
            return Compiler.compile(model, new LinkedHashMap<>());
        } catch (org.miron.runtime.roqme.model.ModelException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /** Runs the whole duration and returns what it measured. */
    public Result run() {
        provider.start();
        driver.start(0);
        if (decider == null) {
            policy.configuration(setup.io()).forEach((vp, index) -> apply(vp, vp.values().get(index)));
        } else {
            for (VariationPoint vp : setup.io().varpoints()) { // the values the robot starts with, until a decision changes them
                if (decider.applied().get(vp.name()) instanceof JsonNode v) {
                    coverage.varpoint(vp, v, 0);
                }
            }
        }
        instant();
        int sameInstant = 0;
        while (true) {
            long next = Math.min(driver.nextEvent(), Math.min(provider.nextTickTime(), provider.nextDue()));
            if (restartAt >= 0) {
                next = Math.min(next, restartAt);
            }
            if (next <= now) {
                if (++sameInstant > MAX_STEPS_PER_INSTANT) {
                    next = now + 1; // something re-arms itself at once: let time go on
                    sameInstant = 0;
                }
            } else {
                sameInstant = 0;
            }
            next = Math.max(next, now);
            if (next > durationMs) {
                measures.hold(world, (durationMs - now) / 1000.0);
                world.advance(durationMs);
                now = durationMs;
                break;
            }
            if (realTime > 0) {
                next = Math.min(durationMs, Math.max(next, awaitWallClock(next)));
            }
            measures.hold(world, (next - now) / 1000.0);
            now = next;
            List<String> events = driver.step(next);
            measures.instant(world, events);
            driver.publishDue();
            instant();
        }
        Map<String, Double> out = measures.finish(world, durationMs / 1000.0);
        out.put("bt:missionsSucceeded", (double) succeeded);
        out.put("bt:missionsFailed", (double) failed);
        out.put("engine:adaptations", (double) adaptations);
        out.put("engine:solveFailures", (double) solveFailures);
        List<RequirementResult> checked = monitors == null ? List.of() : monitors.finish(durationMs);
        return new Result(out, List.copyOf(world.problems()), timeline, checked, coverage.finish(durationMs));
    }

    private long wallStart = -1;

    /** Waits until the wall clock reaches virtual time {@code t}; returns the virtual time it then is. */
    private long awaitWallClock(long t) {
        if (wallStart < 0) {
            wallStart = System.nanoTime();
        }
        while (true) {
            long elapsed = (long) ((System.nanoTime() - wallStart) / 1e6 * realTime);
            if (elapsed >= t) {
                return elapsed;
            }
            try {
                Thread.sleep(Math.max(1, (long) ((t - elapsed) / realTime)));
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return t;
            }
        }
    }

    /** The provider's due work and ticks, a decision if an input changed, one tick of the tree. */
    private void instant() {
        provider.advanceTo(now);
        feedDerived();
        while (provider.nextTickTime() <= now) {
            Provider.Tick t = provider.tick();
            double[] est = t.estimates();
            measures.estimates(est);
            int i = 0;
            for (RoqmeModel.Belief b : setup.roqme().beliefs()) {
                if (!b.isProperty()) {
                    continue;
                }
                InputSpec in = engineMetrics.get(b.name());
                if (in != null) {
                    inputs.setMetric(in, est[i]);
                }
                if (monitors != null) {
                    monitors.estimate(t.timeMs(), b.name(), est[i]);
                }
                if (inTimeline(t.timeMs()) && Math.abs(est[i] - lastEstimates[i]) > 1e-4) {
                    ObjectNode o = Json.object();
                    o.put("name", b.name());
                    o.put("value", est[i]);
                    timeline.add(new TimelineEvent(t.timeMs(), Topics.ESTIMATE, o));
                    lastEstimates[i] = est[i];
                }
                i++;
            }
        }
        if (decider != null && inputs.version() != seenVersion) {
            InputState.Snapshot snap = inputs.snapshot();
            seenVersion = snap.version();
            Decider.Outcome o = decider.decide(snap, now);
            if (!o.result().solved()) {
                solveFailures++; // the last configuration stays, as in the engine; the run goes on
            } else {
                coverage.decision(o.entry().path("applied"));
            }
            for (Decider.Change c : o.changes()) {
                apply(c.varpoint(), c.value());
                adaptations++;
            }
            if (inTimeline(now) && (!o.changes().isEmpty() || !o.result().solved())) {
                o.entry().remove("solveMs"); // wall-clock time: the report stays the same for the same seed
                timeline.add(new TimelineEvent(now, Topics.DECISION, o.entry()));
            }
        }
        if (restartAt >= 0 && now < restartAt) {
            return;
        }
        restartAt = -1;
        coverage.beforeRootTick();
        NodeStatus status = tree.tickRoot();
        if (status == NodeStatus.SUCCESS) {
            succeeded++;
        } else if (status == NodeStatus.FAILURE) {
            failed++;
        }
        if (status.isCompleted()) {
            restartAt = now + setup.world().restartDelayMs();
        }
        recordSkill();
    }

    private void recordSkill() {
        String skill = world.skill();
        if (!skill.equals(lastSkill) && inTimeline(now)) {
            ObjectNode o = Json.object();
            o.put("name", "skill");
            o.put("type", "enum");
            o.put("value", skill.isEmpty() ? "-" : skill);
            timeline.add(new TimelineEvent(now, Topics.CONTEXT, o));
        }
        lastSkill = skill;
    }

    /** A decision reaches the robot: a behaviour variant, a blackboard value or a component parameter. */
    private void apply(VariationPoint vp, JsonNode value) {
        coverage.varpoint(vp, value, now);
        if (monitors != null) {
            monitors.varpoint(now, vp.name(), value);
        }
        switch (vp.bindingType()) {
            case "bt" -> variants.publish(vp.name(), value.asText());
            case "btport" -> blackboard.publish(vp.name(), value.isNumber() ? (Object) value.asDouble()
                    : value.isBoolean() ? (Object) value.asBoolean() : value.asText());
            case "arch" -> world.setParameter(vp.binding().text("parameter"), value.isBoolean() ? (Object) value.asBoolean() : (Object) value.asDouble());
            default -> {
            }
        }
    }

    /**
     * Derived contexts the engine reads (the hospital's {@code qos.lowBattery}), as the provider
     * computes them: the live provider publishes them on change (docs/roqme-provider.md), so does this.
     */
    private void feedDerived() {
        for (RoqmeModel.Variable v : monitoredDerived) {
            Object value = provider.value(v.id());
            if (value != null && !value.equals(lastMonitoredDerived.put(v.name(), value))) {
                monitors.context(now, v.name(), value);
            }
        }
        for (int i = 0; i < derivedInputs.size(); i++) {
            RoqmeModel.Variable v = derivedInputs.get(i);
            Object value = provider.value(v.id());
            if (value == null || value.equals(lastDerived[i])) {
                continue;
            }
            lastDerived[i] = value;
            InputSpec in = engineContexts.get(v.name());
            if (!"event".equals(in.roqmeType())) {
                toEngine(in, Json.MAPPER.valueToTree(value));
            }
        }
    }

    /** A context value as the engine's input of its type (an event: it happened). */
    private void toEngine(InputSpec in, JsonNode json) {
        switch (in.roqmeType()) {
            case "number" -> inputs.setContext(in, in.type().equals("int") ? (Object) (int) Math.round(json.asDouble()) : (Object) json.asDouble());
            case "boolean" -> inputs.setContext(in, json.asBoolean());
            case "enum" -> inputs.setContext(in, Math.max(0, in.literals().indexOf(json.asText())));
            default -> inputs.setContext(in, Boolean.TRUE);
        }
    }

    /** A context sample to the provider and, when the engine reads it, to the engine. */
    private void publish(Publication p, Object value, boolean changed) {
        JsonNode json = value instanceof Boolean b ? BooleanNode.valueOf(b)
                : value instanceof Double d ? DoubleNode.valueOf(d) : TextNode.valueOf(String.valueOf(value));
        RoqmeModel.Variable v = contexts.get(p.context());
        Object decoded = Literals.fromMessage(json, v.type());
        if (decoded != null) {
            provider.input(roqme.symbols().get(v.id()).slot(), decoded, now);
        }
        InputSpec in = engineContexts.get(p.context());
        if (in != null) {
            toEngine(in, json);
        }
        if (monitors != null) {
            monitors.context(now, p.context(), json);
        }
        if (changed && inTimeline(now)) {
            ObjectNode o = Json.object();
            o.put("name", p.context());
            o.put("type", p.event() != null ? "event" : p.type().kind());
            o.set("value", json);
            timeline.add(new TimelineEvent(now, Topics.CONTEXT, o));
        }
    }

    private static ObjectNode observation(RoqmeModel.Observation decl) {
        ObjectNode o = Json.object();
        o.put("name", decl.name());
        ObservationMessage.putActions(o, decl);
        return o;
    }
}
