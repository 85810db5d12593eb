package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.ContextMessage;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.skill.ParameterChange;
import org.miron.runtime.skill.SkillBehaviour;
import org.miron.runtime.sim.WorldModel.Publication;

/**
 * The mock skill interface's skills acting on a world, on the wall clock: a pushed skill takes the
 * time the world gives it and has its effects there, a change-parameter query sets the world's
 * parameter, the processes run, and the world's contexts go on the bus ({@code roqme.context}, as
 * its publication rules say) for the RoQME provider and the engine. The world's semantics are the
 * simulator's ({@link WorldDriver}); only the clock differs: world time is the wall time since
 * {@link #begin} divided by {@code timeScale} (0.5: the world runs twice as fast).
 */
public final class LiveWorld implements SkillBehaviour {
    private static final Logger LOG = Logger.getLogger(LiveWorld.class.getName());
    private static final int MAX_STEPS = 1000; // steps per advance: something that re-arms at once cannot hang the mock

    private final WorldModel model;
    private final long seed;
    private final double timeScale;
    private final Map<String, String> namespaces;
    private final String busIn;
    private BusClient bus;
    private final Map<Long, SkillHandle> running = new LinkedHashMap<>();
    private volatile boolean beginAsked;
    private WorldDriver driver;
    private Results results;
    private long wallStart = -1;
    private final Map<String, Object> earlyParameters = new LinkedHashMap<>(); // changed before the world began
    private final CountDownLatch begun = new CountDownLatch(1);
    private int toldProblems;
    private String broken; // a world expression that could not run: the world stops, skills fail

    /**
     * @param namespaces each published context's RoQME namespace, by name
     * @param busIn      the broker's XSUB endpoint the contexts are published to
     */
    public LiveWorld(WorldModel model, long seed, double timeScale, Map<String, String> namespaces, String busIn) {
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be a positive number, got " + timeScale);
        }
        this.model = model;
        this.seed = seed;
        this.timeScale = timeScale;
        this.namespaces = Map.copyOf(namespaces);
        this.busIn = busIn;
    }

    /** Starts the world's clock (from any thread): at once, or when the first skill is pushed if earlier. */
    public LiveWorld begin() {
        beginAsked = true;
        return this;
    }

    @Override
    public void start(Results sink, long nowMs) {
        this.results = sink;
        this.bus = new BusClient("world", busIn, null, List.of(), (t, b) -> { }).start();
    }

    /**
     * Waits until the world's clock has started (the first skill pushed, or {@link #begin()} and the
     * mock's next step), at most {@code timeoutMs}; true if it has.
     */
    public boolean awaitStarted(long timeoutMs) throws InterruptedException {
        return begun.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    private boolean started(long nowMs) {
        if (driver == null && beginAsked) {
            wallStart = nowMs;
            driver = new WorldDriver(model, seed, this::publish);
            earlyParameters.forEach(driver.world()::setParameter);
            driver.start(0);
            LOG.info("world started: " + model.source());
            begun.countDown();
        }
        return driver != null;
    }

    private long worldTime(long nowMs) {
        return Math.round((nowMs - wallStart) / timeScale);
    }

    @Override
    public void push(long id, JsonNode skill, long nowMs) {
        beginAsked = true;
        if (!guarded(() -> {
            started(nowMs);
            catchUp(nowMs, true);
            start(id, skill);
        })) {
            results.publish(id, "ERROR", Json.MAPPER.nullNode(), Json.object());
        }
    }

    private void start(long id, JsonNode skill) {
        Map<String, Object> inputs = new LinkedHashMap<>();
        skill.path("in-attribute").fields().forEachRemaining(f -> inputs.put(f.getKey(), value(f.getValue())));
        SkillHandle handle = driver.world().push(new SkillRequest(skill.path("name").asText(), inputs));
        running.put(id, handle);
        handle.result().thenAccept(r -> {
            running.remove(id);
            results.publish(id, r.outcome().name(), Json.MAPPER.nullNode(), Json.object());
        });
        driver.publishDue(); // e.g. Docked := false at the start of a move
    }

    private static Object value(JsonNode v) {
        return v.isNumber() ? (Object) v.asDouble() : v.isBoolean() ? (Object) v.asBoolean() : v.asText();
    }

    @Override
    public void parameter(ParameterChange change, long nowMs) {
        JsonNode v = change.values().path("1");
        Object value = v.isBoolean() ? (Object) v.asBoolean() : (Object) v.asDouble();
        guarded(() -> {
            if (!started(nowMs)) {
                earlyParameters.put(change.parameter(), value);
                return;
            }
            catchUp(nowMs, true);
            driver.world().setParameter(change.parameter(), value);
            driver.publishDue();
        });
    }

    @Override
    public void abortAll(long nowMs) {
        guarded(() -> {
            if (started(nowMs)) {
                catchUp(nowMs, true);
            }
        });
        List.copyOf(running.values()).forEach(SkillHandle::abort);
    }

    /**
     * Runs a step of the world unless an expression of it failed before; one that fails now stops
     * the world (logged once; the running skills fail) instead of the mock. False when stopped.
     */
    private boolean guarded(Runnable step) {
        if (broken != null) {
            return false;
        }
        try {
            step.run();
            return true;
        } catch (RuntimeException e) {
            broken = String.valueOf(e.getMessage());
            LOG.severe("world " + model.source() + " stopped: " + broken);
            List.copyOf(running.values()).forEach(h -> h.result().complete(
                    org.miron.executor.skills.SkillResult.of(org.miron.executor.skills.SkillResult.Outcome.ERROR)));
            return false;
        }
    }

    @Override
    public long nextDue(long nowMs) {
        if (broken != null) {
            return Long.MAX_VALUE;
        }
        if (driver == null) {
            return beginAsked ? nowMs : nowMs + 50;
        }
        long next = driver.nextEvent();
        return next == Long.MAX_VALUE ? Long.MAX_VALUE : wallStart + (long) Math.ceil(next * timeScale);
    }

    @Override
    public void advance(long nowMs) {
        guarded(() -> {
            if (started(nowMs)) {
                catchUp(nowMs, false);
            }
        });
    }

    /**
     * Brings the world to now: what fell due since the last step happens instant by instant at its
     * own world time, as on the virtual clock, so the world's course is the simulator's; only the
     * requests (a push, a parameter) land when the wall clock says. {@code always}: a step at now
     * even if nothing is due (a request arrives).
     */
    private void catchUp(long nowMs, boolean always) {
        World world = driver.world();
        long t = Math.max(worldTime(nowMs), world.now());
        for (int i = 0; i < MAX_STEPS && driver.nextEvent() <= t; i++) {
            driver.step(Math.max(driver.nextEvent(), world.now()));
            driver.publishDue();
        }
        if (always) {
            driver.step(t);
            driver.publishDue();
        }
        List<String> problems = world.problems();
        for (; toldProblems < problems.size(); toldProblems++) {
            LOG.warning("world " + model.source() + ": " + problems.get(toldProblems)); // e.g. a skill sent to no place of the world
        }
    }

    private void publish(Publication p, Object value, boolean changed) {
        String namespace = namespaces.getOrDefault(p.context(), "");
        ObjectNode body = ContextMessage.body(p.context(), namespace, p.event() != null ? "event" : p.type().kind(),
                Json.MAPPER.valueToTree(value), System.currentTimeMillis());
        if (p.event() != null) {
            bus.publish(Topics.CONTEXT, Json.write(body)); // an event happens once: not replayed to late subscribers
        } else {
            bus.publishRetained(ContextMessage.retainKey(namespace, p.context()), Topics.CONTEXT, Json.write(body));
        }
    }

    @Override
    public void close() {
        if (bus != null) {
            bus.close();
        }
    }
}
