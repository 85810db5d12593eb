package org.miron.runtime.roqme;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Bus;
import org.miron.runtime.bus.BusLink;
import org.miron.runtime.bus.ContextMessage;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledBelief;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledObservation;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * The provider as a bus service ({@code miron roqme run}): contexts from {@code roqme.context}, every
 * property's {@code roqme.estimate} each period, {@code roqme.observation} when an observation fires,
 * {@code roqme.status} on bad input and every status interval. One thread runs the provider on the
 * wall clock (ms since the epoch, so cron schedules are in UTC); the bus thread only queues what
 * arrives. A context's time is its arrival time: clocks of other machines are not trusted.
 * Evidence lives in memory unless {@link #state} names a file: a restarted provider without one
 * starts from the references; either way the broker's last-value cache gives it the current
 * contexts back (docs/roqme-provider.md, "Restart").
 */
public final class LiveProvider implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(LiveProvider.class.getName());
    private static final int QUEUE_LIMIT = 100_000;

    private record Arrival(byte[] body, long time) {
    }

    private final CompiledModel model;
    private final long periodMs;
    private final long statusIntervalMs;
    private LongSupplier clock = System::currentTimeMillis;
    private double timeScale = 1.0;
    private final BlockingQueue<Arrival> inbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final ProviderStatus status = new ProviderStatus();
    private final ContextDecoder decoder;
    private final Bus bus;
    private final Thread thread;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private final CountDownLatch subscribed = new CountDownLatch(1);
    /** The last contexts received, to drop the broker's replayed copies (bus thread only). */
    private final Map<String, Boolean> recent = new LinkedHashMap<>(64, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Boolean> eldest) {
            return size() > 1024;
        }
    };
    private volatile boolean running = true;
    private long last; // provider thread only: its clock, never going back
    private long nextStatus; // provider thread only
    private long badSeen; // provider thread only
    private Path stateFile;
    private EvidenceState.Saved saved;
    private long lastSave;
    /** Derived contexts (not events: an event has no value to hold) and what was last published of each. */
    private final List<RoqmeModel.Variable> derived;
    private final Map<String, Object> publishedDerived = new java.util.HashMap<>(); // provider thread only
    private volatile long ticks;
    private volatile long fired;

    public LiveProvider(CompiledModel model, long periodMs, long statusIntervalMs, String busIn, String busOut) {
        this(model, periodMs, statusIntervalMs, BusLink.sockets(busIn, busOut));
    }

    /** @param link the bus: sockets, or a broker's {@code local()} in this process */
    public LiveProvider(CompiledModel model, long periodMs, long statusIntervalMs, BusLink link) {
        if (periodMs <= 0) {
            throw new IllegalArgumentException("the period must be positive, got " + periodMs);
        }
        this.model = model;
        this.periodMs = periodMs;
        this.statusIntervalMs = statusIntervalMs;
        this.decoder = new ContextDecoder(model);
        this.derived = model.model().contexts().stream()
                .filter(v -> v.derived() != null && !v.derived().isNull() && !"eventtype".equals(v.type().kind()))
                .toList();
        this.bus = link.open("roqme", List.of(Topics.CONTEXT), (Bus.QuickHandler) this::arrived) // it only queues
                .onBrokerSync((epoch, first) -> subscribed.countDown());
        this.thread = new Thread(this::loop, "roqme-provider");
    }

    /**
     * Keeps the evidence in {@code file} across restarts (written at most every second and on
     * close); reads it now, so an unreadable file is a start-up error. Call before {@link #start}.
     */
    public LiveProvider state(Path file) throws IOException {
        this.saved = EvidenceState.read(file);
        this.stateFile = file;
        if (saved != null && !saved.model().equals(model.model().model())) {
            LOG.warning("roqme: " + file + " holds the evidence of model " + saved.model() + ", not "
                    + model.model().model() + ": its beliefs are matched by id");
        }
        return this;
    }

    /**
     * Runs the provider on a scaled clock, for a demo that plays its scenario faster (0.4: every
     * model second lasts 0.4 s): the period, survivals, windows and timers stay in model time, so
     * the estimates follow the same curve as at scale 1. Call before {@link #start}.
     */
    public LiveProvider timeScale(double scale) {
        if (!(scale > 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException("the time scale must be a positive number, got " + scale);
        }
        long origin = System.currentTimeMillis();
        this.timeScale = scale;
        this.clock = () -> origin + (long) ((System.currentTimeMillis() - origin) / scale);
        return this;
    }

    public LiveProvider start() {
        bus.start();
        thread.start();
        return this;
    }

    /** Waits until the broker has subscribed to the provider's output. */
    public boolean awaitReady(long timeoutMs) throws InterruptedException {
        return bus.awaitReady(timeoutMs);
    }

    /**
     * Waits until the provider's subscription to the contexts is live and the broker's cache of
     * them replayed: a context published after that reaches it exactly once (one published while
     * subscribing may arrive twice, live and from the cache, which matters to a trend window).
     */
    public boolean awaitSubscribed(long timeoutMs) throws InterruptedException {
        return subscribed.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    /**
     * Whether body is a copy of a context seen lately: the broker replays its cache of a topic to
     * a late subscriber through every matching pipe, so the provider may get a sample twice. A
     * sample with the same {@code time} and value is the same sample; counting it again would
     * break a trend (`decreasing`) or count an `update` twice. Bodies without a time are all kept.
     */
    private boolean repeated(byte[] body) {
        String text = new String(body, StandardCharsets.UTF_8);
        return text.contains("\"time\"") && recent.put(text, Boolean.TRUE) != null;
    }

    private void arrived(String topic, byte[] body) {
        if (repeated(body)) {
            return;
        }
        if (!inbox.offer(new Arrival(body, clock.getAsLong())) && status.overflow.incrementAndGet() % 1000 == 1) {
            LOG.warning("roqme: provider behind, dropping contexts");
        }
    }

    private void loop() {
        long start = clock.getAsLong();
        Provider p = new Provider(model, periodMs, start).onFire(this::publishFiring).start();
        if (saved != null) {
            p.restore(saved.beliefs(), Math.max(0, start - saved.time()));
            LOG.info("roqme: evidence restored from " + stateFile + " (saved " + (start - saved.time()) + " ms ago)");
        }
        lastSave = start;
        last = start;
        nextStatus = start;
        publishStatus(start);
        publishDerived(p, start);
        try {
            while (running) {
                try {
                    round(p);
                } catch (RuntimeException e) { // a bug must not silence the metrics: log it and go on
                    LOG.severe("roqme: unexpected failure, continuing: " + e);
                    Thread.sleep(100);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            if (stateFile != null) {
                save(p, clock.getAsLong());
            }
            stopped.countDown();
        }
    }

    /** One round of the provider thread: the inputs that arrived, what is due, ticks, status. */
    private void round(Provider p) throws InterruptedException {
        long now = clock.getAsLong();
        long wait = Math.min(p.nextTickTime(), Math.min(p.nextDue(), nextStatus)) - now;
        Arrival a = wait > 0 ? inbox.poll(Math.max(1, (long) Math.ceil(wait * timeScale)), TimeUnit.MILLISECONDS) : inbox.poll();
        while (a != null) {
            last = Math.max(last, a.time()); // the provider's clock never goes back
            input(p, a, last);
            a = inbox.poll();
        }
        now = Math.max(last, clock.getAsLong());
        p.advanceTo(now);
        while (p.nextTickTime() <= now) {
            publishTick(p.tick());
            ticks++;
        }
        publishDerived(p, now);
        if (stateFile != null && now - lastSave >= Math.max(1000, periodMs)) {
            save(p, now);
        }
        last = now;
        if (status.badTotal() != badSeen || now >= nextStatus) {
            badSeen = status.badTotal();
            publishStatus(now);
            nextStatus = now + statusIntervalMs;
        }
    }

    private void save(Provider p, long now) {
        lastSave = now;
        try {
            // the evidence as of the last tick: its ages count from that tick's time
            EvidenceState.write(stateFile, model.model().model(), p.nextTickTime() - periodMs, p.evidence());
        } catch (IOException | RuntimeException e) {
            LOG.warning("roqme: cannot write the state file " + stateFile + ": " + e.getMessage());
        }
    }

    private void input(Provider p, Arrival a, long time) {
        try {
            ContextDecoder.Sample s = decoder.decode(a.body());
            if (s == null) {
                return; // our own derived context, back from the bus
            }
            status.contexts.incrementAndGet();
            p.input(s.slot(), s.value(), time);
        } catch (ContextDecoder.BadContext e) {
            status.bad(e.problem, e.getMessage(), time);
            long n = status.badTotal();
            if (n <= 10 || n % 1000 == 0) {
                LOG.warning("roqme: dropped a context (" + n + " so far): " + e.getMessage());
            }
        }
    }

    private void publishTick(Provider.Tick t) {
        long now = clock.getAsLong();
        int i = 0;
        for (CompiledBelief b : model.beliefs()) {
            if (!b.decl().isProperty()) {
                continue;
            }
            ObjectNode o = Json.object();
            o.put("name", b.decl().name());
            o.put("namespace", b.decl().namespace());
            o.put("value", t.estimates()[i++]);
            o.put("time", now);
            bus.publishRetained("estimate\0" + b.decl().namespace() + "\0" + b.decl().name(), Topics.ESTIMATE, Json.write(o));
        }
    }

    /**
     * Publishes every derived context whose value changed (and each once it is known) on
     * {@code roqme.context} with {@code "derived": true}: the engine reads them like any context
     * (a MIRoN rule on {@code qos.lowBattery}, seed §3), and the provider skips them when they
     * come back. Retained, so a restarted broker's cache gets them again.
     */
    private void publishDerived(Provider p, long now) {
        for (RoqmeModel.Variable v : derived) {
            Object value = p.value(v.id());
            if (value == null || value.equals(publishedDerived.get(v.id()))) {
                continue;
            }
            publishedDerived.put(v.id(), value);
            ObjectNode o = ContextMessage.body(v.name(), v.namespace(), v.type().kind(), Json.MAPPER.valueToTree(value), now);
            o.put("derived", true);
            bus.publishRetained(ContextMessage.retainKey(v.namespace(), v.name()), Topics.CONTEXT, Json.write(o));
        }
    }

    private void publishFiring(CompiledObservation obs, long time) {
        fired++;
        ObjectNode o = Json.object();
        o.put("name", obs.decl().name());
        o.put("namespace", obs.decl().namespace());
        o.put("time", time);
        ObservationMessage.putActions(o, obs.decl());
        bus.publish(Topics.OBSERVATION, Json.write(o));
    }

    private void publishStatus(long now) {
        bus.publishRetained("status", Topics.ROQME_STATUS,
                status.body(model.model().model(), now, ticks, fired, "ok"));
    }

    /** Contexts received and accepted; rejected ones by kind (for tests and the status topic). */
    public long contexts() {
        return status.contexts.get();
    }

    /** Observations fired so far. */
    public long fired() {
        return fired;
    }

    public long rejected() {
        return status.badTotal();
    }

    @Override
    public void close() {
        running = false;
        thread.interrupt();
        try {
            stopped.await(2, TimeUnit.SECONDS);
            bus.flush(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        bus.close();
    }
}
