package org.miron.runtime.sim;

import java.util.List;
import java.util.Objects;
import org.miron.executor.scripting.ScriptValues;
import org.miron.runtime.sim.WorldModel.Publication;

/**
 * A world and the contexts it publishes, stepped by whoever owns the clock: the simulator on its
 * virtual clock ({@link Simulation}) and the live skill interface on the wall clock
 * ({@link LiveWorld}). One step at time t lets the rates act until t, ends the skills and runs the
 * processes due, publishes the events that occurred; {@link #publishDue} then publishes the
 * periodic contexts due and those published on change whose value changed. Single-threaded.
 */
public final class WorldDriver {
    /** Where the published contexts go: a value (Double, Boolean or String) or, for an event, TRUE. */
    public interface Sink {
        void context(Publication publication, Object value, boolean changed);
    }

    private final World world;
    private final List<Publication> publications;
    private final Sink sink;
    private final Object[] lastPublished;
    private final long[] nextPublish;

    public WorldDriver(WorldModel model, long seed, Sink sink) {
        this.world = new World(model, seed);
        this.publications = model.publications();
        this.sink = sink;
        this.lastPublished = new Object[publications.size()];
        this.nextPublish = new long[publications.size()];
    }

    public World world() {
        return world;
    }

    /** Starts the world at time {@code t} and publishes every context once. */
    public void start(long t) {
        world.start(t);
        publish(true);
    }

    /** The next time something happens by itself: a skill ends, a process occurs, a context is due. */
    public long nextEvent() {
        long next = world.nextEvent();
        for (long p : nextPublish) {
            next = Math.min(next, p);
        }
        return next;
    }

    /** Moves the world to {@code t} and does what is due then; returns the events that occurred, in order. */
    public List<String> step(long t) {
        world.advance(t);
        world.fire();
        List<String> events = world.takeEvents();
        for (String event : events) {
            for (Publication p : publications) {
                if (event.equals(p.event())) {
                    sink.context(p, Boolean.TRUE, true);
                }
            }
        }
        return events;
    }

    /** Publishes the periodic contexts that are due and those published on change whose value changed. */
    public void publishDue() {
        publish(false);
    }

    private void publish(boolean all) {
        long now = world.now();
        for (int i = 0; i < publications.size(); i++) {
            Publication p = publications.get(i);
            if (p.value() == null) {
                nextPublish[i] = Long.MAX_VALUE; // an event: published when it occurs
                continue;
            }
            boolean due = all || (p.everyMs() != null && nextPublish[i] <= now);
            Object v = due || p.everyMs() == null ? value(p) : null;
            if (due || (p.everyMs() == null && !Objects.equals(v, lastPublished[i]))) {
                sink.context(p, v, !Objects.equals(v, lastPublished[i]));
                lastPublished[i] = v;
            }
            if (p.everyMs() != null) {
                nextPublish[i] = due ? now + p.everyMs() : nextPublish[i];
            } else {
                nextPublish[i] = Long.MAX_VALUE;
            }
        }
    }

    private Object value(Publication p) {
        Object raw = world.eval(p.value());
        return switch (p.type().kind()) {
            case "boolean" -> ScriptValues.toBoolean(raw);
            case "enum" -> String.valueOf(raw);
            default -> ScriptValues.toDouble(raw);
        };
    }
}
