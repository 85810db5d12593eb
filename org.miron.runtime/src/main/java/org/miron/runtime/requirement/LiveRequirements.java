package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.LongSupplier;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Bus;
import org.miron.runtime.bus.BusLink;
import org.miron.runtime.bus.Topics;

/**
 * The requirement monitors beside the engine on the bus (docs/requirements.md, "Checking live"):
 * fed with {@code roqme.context}, {@code roqme.estimate} and the decisions of {@code miron.decision},
 * each at its arrival on the component's own clock (ms since it started), and told every
 * violation and met-again on {@code miron.requirement}, its counts on
 * {@code miron.requirement.status}. The bus thread only queues what arrives; one monitor thread
 * takes it every {@link #BATCH_MS}, decodes and feeds it (the monitors are not thread-safe) and
 * advances time then, so that a deadline passes without a message. Bad bus input is counted and
 * logged once per kind, never fatal.
 */
public final class LiveRequirements implements AutoCloseable {
    /** The shortest interval of {@code miron.requirement.status}. */
    public static final long TICK_MS = 100;
    /** How long the monitors let bus input gather before they take it. */
    static final long BATCH_MS = 20;
    private static final Logger LOG = Logger.getLogger(LiveRequirements.class.getName());
    private static final int QUEUE_LIMIT = 100_000;

    /** What arrived (or, with {@code done} set, the request to finish), stamped with the clock. */
    private record Arrival(String topic, byte[] body, long time, CompletableFuture<List<RequirementResult>> done) {
    }

    private final RequirementModel model;
    private final RequirementMonitors monitors;
    private final RequirementTally tally;
    private final Bus bus;
    private final Thread thread;
    private final BlockingQueue<Arrival> inbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final CountDownLatch subscribed = new CountDownLatch(1);
    private final CountDownLatch stopped = new CountDownLatch(1);
    private final Set<String> badKindsLogged = new HashSet<>(); // monitor thread only
    private final AtomicLong contextsIn = new AtomicLong();
    private final AtomicLong estimatesIn = new AtomicLong();
    private final AtomicLong decisionsIn = new AtomicLong();
    private final AtomicLong badBusInput = new AtomicLong();
    private final AtomicLong dropped = new AtomicLong();
    private LongSupplier clock;
    private long statusIntervalMs = 5000;
    private Consumer<RequirementEvent> listener = e -> {
    };
    private volatile boolean running = true;
    private volatile List<RequirementResult> results;
    private long last; // monitor thread only: the clock, never going back

    /** Compiles the model's formulas (an IllegalArgumentException names one the monitors cannot run). */
    public LiveRequirements(RequirementModel model, String busIn, String busOut) {
        this(model, BusLink.sockets(busIn, busOut));
    }

    /** The same, on a given bus link: sockets, or a broker's {@code local()} in this process. */
    public LiveRequirements(RequirementModel model, BusLink link) {
        this.model = model;
        this.monitors = new RequirementMonitors(model);
        this.tally = new RequirementTally(model);
        long origin = System.nanoTime();
        this.clock = () -> (System.nanoTime() - origin) / 1_000_000;
        this.bus = link.open("requirements", List.of(Topics.CONTEXT, Topics.ESTIMATE, Topics.DECISION),
                (Bus.QuickHandler) this::arrived) // it only queues
                .onBrokerSync((epoch, first) -> subscribed.countDown());
        this.thread = new Thread(this::loop, "requirement-monitors");
        this.thread.setDaemon(true);
    }

    /**
     * The monitors' clock, ms since the start of the run, not decreasing: a test's, or the demo's
     * world time at its time scale, so that {@code within 5 seconds} is 5 s of the world. Before {@link #start}.
     */
    public LiveRequirements clock(LongSupplier msSinceStart) {
        this.clock = msSinceStart;
        return this;
    }

    /** How often {@code miron.requirement.status} is published besides at start, on events and at the end (5000). */
    public LiveRequirements statusInterval(long ms) {
        this.statusIntervalMs = Math.max(TICK_MS, ms);
        return this;
    }

    /** Also tells every event in process (on the monitor thread), e.g. to a console. Before {@link #start}. */
    public LiveRequirements onEvent(Consumer<RequirementEvent> eventListener) {
        this.listener = eventListener;
        return this;
    }

    public RequirementModel model() {
        return model;
    }

    public LiveRequirements start() {
        monitors.onEvent(this::told);
        bus.start();
        thread.start();
        return this;
    }

    /** Waits until the subscriptions are live and the broker's cache of the inputs replayed. */
    public boolean awaitSubscribed(long timeoutMs) throws InterruptedException {
        return subscribed.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    private void arrived(String topic, byte[] body) {
        if (!running) {
            return;
        }
        if (!inbox.offer(new Arrival(topic, body, clock.getAsLong(), null)) && dropped.incrementAndGet() % 1000 == 1) {
            LOG.warning("requirements: monitors behind, dropping bus input");
        }
    }

    private void loop() {
        last = Math.max(0, clock.getAsLong());
        long nextStatus = last;
        try {
            while (results == null) {
                // In batches: a sleep, then all that arrived. The monitors then never wake on a
                // message, so they stay off the way of the estimate to the engine's decision on a
                // robot's few cores; a verdict's time is its input's arrival stamp all the same,
                // only its message may leave up to BATCH_MS later.
                Thread.sleep(BATCH_MS);
                Arrival a = inbox.poll();
                while (a != null && results == null) {
                    last = Math.max(last, a.time());
                    if (a.done() != null) {
                        finish(a.done());
                    } else {
                        input(a);
                    }
                    a = inbox.poll();
                }
                if (results != null) {
                    break;
                }
                last = Math.max(last, clock.getAsLong());
                monitors.advance(last);
                if (last >= nextStatus) {
                    publishStatus();
                    nextStatus = last + statusIntervalMs;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) { // a bug: say so, the run goes on without its requirement checks
            LOG.severe("requirements: monitors stopped: " + e);
        } finally {
            stopped.countDown();
        }
    }

    private void finish(CompletableFuture<List<RequirementResult>> done) {
        List<RequirementResult> r = monitors.finish(last);
        tally.finished(r);
        results = r;
        publishStatus();
        done.complete(r);
    }

    private void input(Arrival a) {
        JsonNode body;
        try {
            body = Json.MAPPER.readTree(a.body());
        } catch (IOException e) {
            body = null;
        }
        if (body == null || !body.isObject()) {
            bad(a.topic(), "not a JSON object");
            return;
        }
        try {
            switch (a.topic()) {
                case Topics.CONTEXT -> context(body);
                case Topics.ESTIMATE -> estimate(body);
                case Topics.DECISION -> decision(body);
                default -> bad(a.topic(), "not a topic of the requirement monitors");
            }
        } catch (RuntimeException e) { // bad input must not stop the checks
            bad(a.topic(), "not taken: " + e.getMessage());
        }
    }

    private void context(JsonNode body) {
        JsonNode name = body.path("name");
        if (!name.isTextual() || !body.has("value")) {
            bad(Topics.CONTEXT, "no 'name' or no 'value'");
            return;
        }
        contextsIn.incrementAndGet();
        if (monitors.contexts().contains(name.asText()) && monitors.context(last, name.asText(), body.get("value"))) {
            tally.valued("context", name.asText());
        }
    }

    private void estimate(JsonNode body) {
        JsonNode name = body.path("name");
        JsonNode value = body.path("value");
        if (!name.isTextual() || !value.isNumber()) {
            bad(Topics.ESTIMATE, "no 'name' or no numeric 'value'");
            return;
        }
        estimatesIn.incrementAndGet();
        if (monitors.properties().contains(name.asText())) {
            monitors.estimate(last, name.asText(), value.asDouble());
            tally.valued("property", name.asText());
        }
    }

    /** The values the engine applied: a {@code null} (nothing applied yet) is no value. */
    private void decision(JsonNode body) {
        JsonNode decisions = body.path("decisions");
        if (!decisions.isObject()) {
            bad(Topics.DECISION, "no 'decisions' object");
            return;
        }
        decisionsIn.incrementAndGet();
        decisions.fields().forEachRemaining(d -> {
            if (!d.getValue().isNull() && monitors.varpoint(last, d.getKey(), d.getValue())) {
                tally.valued("varpoint", d.getKey());
            }
        });
    }

    private void bad(String topic, String problem) {
        badBusInput.incrementAndGet();
        if (badKindsLogged.add(topic + ": " + problem)) {
            LOG.warning("requirements: bad input on " + topic + " (" + problem + "), counted in badBusInput; "
                    + "further ones of this kind are not logged");
        }
    }

    private void told(RequirementEvent e) {
        tally.told(e);
        ObjectNode o = Json.object();
        o.put("name", e.name());
        o.put("verdict", e.verdict());
        o.put("time", e.timeMs() / 1000.0);
        o.put("detected", e.detectedMs() / 1000.0);
        ObjectNode values = o.putObject("values");
        for (Map.Entry<String, Object> v : e.values().entrySet()) {
            values.set(v.getKey(), Json.MAPPER.valueToTree(v.getValue()));
        }
        bus.publish(Topics.REQUIREMENT, Json.write(o));
        try {
            listener.accept(e);
        } catch (RuntimeException x) {
            LOG.warning("requirements: event listener failed: " + x);
        }
        publishStatus();
    }

    private void publishStatus() {
        ObjectNode o = Json.object();
        o.put("time", last / 1000.0);
        o.put("model", model.model());
        o.put("state", results == null ? "running" : "finished");
        o.set("requirements", tally.json());
        ObjectNode c = o.putObject("counters");
        c.put("contextsIn", contextsIn.get());
        c.put("estimatesIn", estimatesIn.get());
        c.put("decisionsIn", decisionsIn.get());
        c.put("rejected", monitors.rejected());
        c.put("badBusInput", badBusInput.get());
        bus.publishRetained("status", Topics.REQUIREMENT_STATUS, Json.write(o));
    }

    /**
     * Ends the run now: every window still open is decided (OPEN where it reaches past now), the
     * last events and the final status are published; returns each requirement's result, in
     * order. Later calls return the same results; null if the monitors stopped on a failure.
     */
    public List<RequirementResult> finish() throws InterruptedException {
        if (results != null || !thread.isAlive()) {
            return results;
        }
        CompletableFuture<List<RequirementResult>> done = new CompletableFuture<>();
        inbox.put(new Arrival(null, null, clock.getAsLong(), done));
        try {
            return done.get(5, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException e) {
            return results;
        }
    }

    public long contextsIn() {
        return contextsIn.get();
    }

    public long estimatesIn() {
        return estimatesIn.get();
    }

    public long decisionsIn() {
        return decisionsIn.get();
    }

    public long badBusInput() {
        return badBusInput.get();
    }

    /** Finishes the run if {@link #finish} was not called, lets the last messages leave, stops. */
    @Override
    public void close() {
        running = false;
        try {
            if (thread.isAlive()) {
                finish();
            }
            stopped.await(2, TimeUnit.SECONDS);
            bus.flush(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        thread.interrupt();
        bus.close();
    }
}
