package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Bus;
import org.miron.runtime.bus.BusLink;
import org.miron.runtime.bus.Topics;

/**
 * The adaptation engine. Threads: the bus client (inputs in, outputs out), the solve loop (one
 * solve at a time on the latest inputs) and the parameter sender (acknowledged change-parameter
 * queries). Nothing an input or a solver does ends the solve loop.
 */
public final class Engine implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(Engine.class.getName());

    private final IoModel model;
    private final SolverBackend backend;
    private final EngineOptions options;
    private final InputState state;
    private final InputDecoder decoder;
    private final EngineStatus status;
    private final Decider decider; // solve thread only
    private volatile Map<String, Object> appliedValues = Map.of();
    private Bus bus;
    private ParameterSender sender;
    private DecisionLog log;
    private Thread loop;
    private volatile boolean running;
    private volatile long lastStatusNanos = System.nanoTime();
    private long seq;
    private final CountDownLatch replayed = new CountDownLatch(1); // counted down by the first broker sync

    public Engine(IoModel model, SolverBackend backend, EngineOptions options) {
        this.model = model;
        this.backend = backend;
        this.options = options;
        this.state = new InputState(model);
        this.decoder = new InputDecoder(model, state);
        this.status = new EngineStatus(model.model(), backend.name());
        this.decider = new Decider(model, backend, state, status);
        appliedValues = decider.applied();
    }

    /** The name of the backend that decides (native, minizinc, both). */
    public String backendName() {
        return backend.name();
    }

    /** Loads the io.json and builds the backend named in the options. */
    public static Engine create(EngineOptions options) throws EngineStartException {
        IoModel model;
        try {
            model = IoModel.load(options.ioJson);
        } catch (IllegalArgumentException e) {
            throw new EngineStartException("invalid io.json: " + e.getMessage());
        }
        return new Engine(model, Backends.create(options.backend, model, options), options);
    }

    public Engine start() throws EngineStartException {
        try {
            backend.check();
        } catch (BackendUnavailableException e) {
            throw new EngineStartException(e.getMessage());
        }
        if (options.decisionLog != null) {
            try {
                log = new DecisionLog(options.decisionLog);
            } catch (IOException e) {
                throw new EngineStartException("cannot open decision log " + options.decisionLog + ": " + e.getMessage());
            }
        }
        running = true;
        BusLink link = options.bus != null ? options.bus : BusLink.sockets(options.busIn, options.busOut);
        // onMessage decodes into the input state and wakes the solve loop: quick
        bus = link.open("engine", List.of("roqme.", Topics.OVERRIDE_PREFIX), (Bus.QuickHandler) this::onMessage)
                .onBrokerSync(this::onBrokerSync).start();
        sender = new ParameterSender(options.request, options.ackTimeoutMs, options.backoffMinMs,
                options.backoffMaxMs, new SenderReports()).start();
        loop = new Thread(this::solveLoop, "engine-solve");
        loop.setDaemon(true);
        loop.start();
        LOG.info("engine: model " + model.model() + ", backend " + backend.name() + ", bus "
                + (options.bus != null ? "in process" : options.busIn + " / " + options.busOut) + ", requests " + options.request);
        return this;
    }

    private void onMessage(String topic, byte[] body) {
        if (topic.equals(Topics.OBSERVATION) || topic.equals(Topics.ROQME_STATUS)) {
            return; // the RoQME provider's own outputs, not inputs
        }
        try {
            decoder.apply(topic, body);
        } catch (BadInputException e) {
            String counter = switch (e.kind()) {
                case MALFORMED -> "malformedInput";
                case UNKNOWN -> "unknownInput";
                case TYPE -> "badTypeInput";
            };
            status.count(counter);
            status.error(counter, topic + ": " + e.getMessage());
            LOG.warning("dropped " + topic + " message: " + e.getMessage());
            publishStatus();
        }
    }

    /** The broker has replayed its cache of our prefixes (first epoch), or restarted (later ones). */
    private void onBrokerSync(String epoch, boolean first) {
        if (first) {
            replayed.countDown();
        } else {
            LOG.info("engine: broker restarted (epoch " + epoch + "), inputs replayed");
        }
    }

    /**
     * Before the first decision, waits for the broker's replay of the current inputs (bounded by
     * the settle time): a decision from the initial values would move a robot that is, say,
     * charging, until the replay of {@code power_autonomy} corrects it a moment later.
     */
    private void awaitReplay() throws InterruptedException {
        if (replayed.await(options.settleMs, TimeUnit.MILLISECONDS)) {
            LOG.info("engine: inputs replayed by the broker, first solve");
        } else {
            LOG.info("engine: no broker replay within " + options.settleMs + " ms, first solve from what arrived");
        }
    }

    private void solveLoop() {
        try {
            awaitReplay();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return;
        }
        long seen = 0;
        SolveRetry retry = new SolveRetry(options.solveRetryMinMs, options.solveRetryMaxMs);
        while (running) {
            try {
                InputState.Snapshot snap = state.awaitChange(seen, retry.waitMs(200));
                if (snap == null && retry.due()) {
                    snap = state.snapshot(); // same inputs, the last solve failed: try again
                    status.count("solveRetries");
                    LOG.info("retrying the failed solve on unchanged inputs");
                }
                if (snap == null) {
                    heartbeat();
                    continue;
                }
                seen = snap.version();
                SolveResult r = backend.solve(snap.params());
                if (running) {
                    handle(r, snap);
                    retry.after(r);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            } catch (RuntimeException e) { // a bug must not stop adaptation: report and go on
                LOG.severe("solve loop: " + e);
                status.error("internal", String.valueOf(e));
                publishStatus();
            }
        }
    }

    private void handle(SolveResult r, InputState.Snapshot snap) {
        Decider.Outcome o = decider.handle(r, snap, System.currentTimeMillis());
        appliedValues = decider.applied();
        if (o.result().solved()) {
            seq = decider.seq();
            // The state first (above), then the outputs: they leave at once, and whoever sees one may ask.
            for (Decider.Change c : o.changes()) {
                send(c.varpoint(), c.value());
            }
            bus.publishRetained(Topics.DECISION, Topics.DECISION, Json.write(o.entry()));
        }
        if (log != null) {
            log.append(o.entry());
        }
        publishStatus();
    }

    private void send(VariationPoint vp, JsonNode value) {
        String type = vp.bindingType();
        if (type.equals("bt") || type.equals("btport")) {
            ObjectNode msg = Json.object();
            msg.put("varpoint", vp.name());
            msg.set("value", value);
            msg.put("seq", seq);
            msg.put("time", System.currentTimeMillis());
            String prefix = type.equals("bt") ? Topics.VARIANT_PREFIX : Topics.BLACKBOARD_PREFIX;
            bus.publishRetained(prefix + vp.name(), prefix + vp.name(), Json.write(msg));
        } else if (type.equals("arch")) {
            sender.submit(vp.name(), ParameterSender.changeParameter(vp.binding(), value));
        }
    }

    private void publishStatus() {
        lastStatusNanos = System.nanoTime();
        bus.publishRetained(Topics.STATUS, Topics.STATUS, Json.write(status.toJson(appliedValues)));
    }

    /** A quiet engine still shows it is alive. */
    private void heartbeat() {
        if (System.nanoTime() - lastStatusNanos >= options.statusIntervalMs * 1_000_000L) {
            publishStatus();
        }
    }

    /** Counters and last error (tests, diagnostics). */
    public EngineStatus status() {
        return status;
    }

    /** The configuration in force: varpoint → value. */
    public Map<String, Object> applied() {
        return appliedValues;
    }

    public boolean isAlive() {
        return running && loop.isAlive();
    }

    public IoModel model() {
        return model;
    }

    @Override
    public void close() {
        running = false;
        if (loop != null) {
            loop.interrupt();
            try {
                loop.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (sender != null) {
            sender.close();
        }
        if (bus != null) {
            try {
                bus.flush(500);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            bus.close();
        }
        if (log != null) {
            log.close();
        }
        backend.close();
    }

    /** Parameter sender progress → counters and status. */
    private final class SenderReports implements ParameterSender.Listener {
        @Override
        public void sent(String key, ObjectNode query) {
            status.count("paramSent");
        }

        @Override
        public void acked(String key, ObjectNode query) {
            status.count("paramAcked");
            LOG.info("change-parameter acknowledged: " + query.path("query").path("Parameter").asText() + " = "
                    + query.path("query").path("values").path("1"));
        }

        @Override
        public void retry(String key, ObjectNode query, int attempt, long backoffMs) {
            status.count("paramRetries");
            status.error("parameter", "no ack for " + key + " (attempt " + attempt + "), retrying in " + backoffMs + " ms");
            publishStatus();
        }
    }
}
