package org.miron.cli.run;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.function.Consumer;
import java.util.logging.Logger;

import org.miron.dds.Bridge;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.transport.DdsException;
import org.miron.dds.transport.IhmcTransport;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusLink;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.EngineStartException;
import org.miron.runtime.requirement.LiveRequirements;
import org.miron.runtime.requirement.RequirementEvent;
import org.miron.runtime.roqme.LiveProvider;

/**
 * The MIRoN side of a robot in one process ({@code miron run}): the broker on its endpoints, then
 * the requirement monitors and the RoQME provider (each waits until the broker has replayed its
 * cache to it), the optional DDS bridge, and the engine last, so that its first decision reaches
 * monitors that listen. They reach the broker through its local links, without sockets; external
 * peers (executor, skill interface, the robot's contexts) see the same wire as with the separate
 * components. All or nothing: if one component cannot start, the
 * ones already started are closed and {@link StartException} says why.
 */
public final class RobotSide implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(RobotSide.class.getName());
    private static final long SUBSCRIBE_MS = 10_000;
    /** How the start-up lines name the components' link to the broker. */
    static final String IN_PROCESS = "bus in process (no sockets to the broker)";

    /** A component could not start; nothing runs. */
    public static final class StartException extends Exception {
        StartException(String message) {
            super(message);
        }
    }

    /** What to run, as the separate commands' options say it. */
    public static final class Options {
        public Endpoints endpoints = Endpoints.defaults();
        public Path cacheFile;
        public long periodMs = 1000;
        public long providerStatusMs = 5000;
        public EngineOptions engine;
        /** The bridge's mapping, or null: no bridge. */
        public BridgeConfig bridge;
        public long bridgeStatusMs = 5000;
    }

    private final RunModel model;
    private final Options options;
    private final Deque<AutoCloseable> running = new ArrayDeque<>();
    private Consumer<String> say = s -> { };
    private Consumer<RequirementEvent> onRequirement = e -> { };

    public RobotSide(RunModel model, Options options) {
        this.model = model;
        this.options = options;
    }

    /** Told one line per component as it starts, with its endpoints. Before {@link #start}. */
    public RobotSide onStarted(Consumer<String> line) {
        this.say = line;
        return this;
    }

    /** Told every requirement event (violation, met again) as the monitors see it. Before {@link #start}. */
    public RobotSide onRequirement(Consumer<RequirementEvent> listener) {
        this.onRequirement = listener;
        return this;
    }

    /** A console printer for {@link #onStarted}: {@code prefix + line}, flushed. */
    public static Consumer<String> printer(PrintWriter out, String prefix) {
        return s -> {
            out.println(prefix + s);
            out.flush();
        };
    }

    public RobotSide start() throws StartException, InterruptedException {
        try {
            startAll();
        } catch (StartException | InterruptedException | RuntimeException e) {
            close();
            throw e;
        }
        return this;
    }

    private void startAll() throws StartException, InterruptedException {
        Endpoints ep = options.endpoints;
        EngineOptions eo = options.engine;
        eo.busIn = ep.busIn();
        eo.busOut = ep.busOut();
        eo.request = ep.request();
        Engine engine;
        try {
            engine = Engine.create(eo); // the io.json and the backend, before any socket
        } catch (EngineStartException e) {
            throw new StartException("engine: " + e.getMessage());
        }
        Broker broker;
        try {
            broker = new Broker(ep, options.cacheFile).start();
        } catch (IllegalStateException e) {
            engine.close();
            throw new StartException(e.getMessage());
        }
        running.push(broker);
        running.push(engine); // closed first, whether it started or not
        BusLink local = broker.local(); // the components here reach the broker without sockets
        eo.bus = local;
        say.accept("broker: requests " + ep.request() + " -> skill interface " + ep.skill() + ", bus " + ep.busIn()
                + " -> " + ep.busOut() + (options.cacheFile == null ? "" : ", cache file " + options.cacheFile));
        if (model.requirements() != null) {
            LiveRequirements checks;
            try {
                checks = new LiveRequirements(model.requirements(), local).onEvent(onRequirement);
            } catch (IllegalArgumentException e) {
                throw new StartException("requirement monitors: " + e.getMessage());
            }
            running.push(checks);
            checks.start();
            if (!checks.awaitSubscribed(SUBSCRIBE_MS)) {
                throw new StartException("requirement monitors: did not connect to the bus within " + SUBSCRIBE_MS / 1000 + " s");
            }
            say.accept("requirements: " + model.requirements().requirements().size() + " monitored ("
                    + String.join(", ", model.requirements().requirements().stream().map(r -> r.name()).toList())
                    + "), " + IN_PROCESS);
        }
        if (model.roqme() != null) {
            LiveProvider provider = new LiveProvider(model.roqme(), options.periodMs, options.providerStatusMs, local);
            running.push(provider);
            provider.start();
            if (!provider.awaitSubscribed(SUBSCRIBE_MS)) {
                throw new StartException("roqme provider: did not connect to the bus within " + SUBSCRIBE_MS / 1000 + " s");
            }
            say.accept("roqme provider: model " + model.roqme().model().model() + ", "
                    + model.roqme().model().beliefs().stream().filter(b -> b.isProperty()).count() + " properties, "
                    + model.roqme().observations().size() + " observations, period " + options.periodMs + " ms, "
                    + IN_PROCESS);
        } else {
            say.accept("roqme provider: not run (the estimates come from elsewhere)");
        }
        if (options.bridge != null) {
            BridgeConfig c = options.bridge;
            Bridge bridge;
            try {
                bridge = new Bridge(c, new IhmcTransport(c.domain(), c.name(), c.interfaces(), c.types()), local, ep.skill(),
                        options.bridgeStatusMs).start();
            } catch (DdsException | RuntimeException e) {
                throw new StartException("dds-bridge: " + e.getMessage());
            }
            running.push(bridge);
            say.accept("dds-bridge: domain " + c.domain() + ", " + c.contexts().size() + " context topics, "
                    + c.decisions().size() + " decision topics, " + c.estimates().size() + " estimate topics"
                    + (c.answersParameters() ? ", change-parameter answered on " + ep.skill() : "")
                    + ", " + IN_PROCESS);
        }
        running.remove(engine);
        running.push(engine);
        try {
            engine.start();
        } catch (EngineStartException e) {
            throw new StartException("engine: " + e.getMessage());
        }
        say.accept("engine: model " + engine.model().model() + ", backend " + engine.backendName() + ", " + IN_PROCESS
                + ", requests " + ep.request()
                + (eo.decisionLog == null ? "" : ", decision log " + eo.decisionLog));
    }

    /** Stops the components, the last started first, then deletes the generated model. */
    @Override
    public void close() {
        while (!running.isEmpty()) {
            AutoCloseable c = running.pop();
            try {
                c.close();
            } catch (Exception e) {
                LOG.warning("run: " + c.getClass().getSimpleName() + " did not stop cleanly: " + e);
            }
        }
        model.close();
    }
}
