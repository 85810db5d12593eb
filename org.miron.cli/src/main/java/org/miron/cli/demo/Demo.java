package org.miron.cli.demo;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.miron.cli.ModelNames;
import org.miron.cli.monitor.LiveMonitor;
import org.miron.cli.monitor.MonitorServer;
import org.miron.executor.NodeStatus;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.EngineStartException;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.requirement.RequirementResult;
import org.miron.runtime.player.ScenarioPlayer;
import org.miron.runtime.recording.Btlog;
import org.miron.runtime.recording.BusLog;
import org.miron.runtime.roqme.LiveProvider;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.runtime.skill.TableSkills;
import org.miron.runtime.sim.LiveWorld;

/**
 * The whole MIRoN loop in one JVM: broker, RoQME QoS Metrics Provider, adaptation engine, mock
 * skill interface and BT executor. Closed-loop ({@link #world}): the mock's skills act on a
 * simulated world, which publishes the robot's contexts, so what the robot does (its speed, where
 * it goes, docking) changes what it perceives. Scripted: a scenario player publishes the contexts
 * whatever the robot does, and the skills take a table's times. The robot runs its mission over and
 * over meanwhile; every perception, fired observation, metric move, adaptation and skill is told on
 * the console, and at the end a timeline report is written. Without a provider the scenario's own
 * estimate lines are the metrics.
 */
public final class Demo {
    /** What a run produced. */
    public record Result(int adaptations, int parameterChanges, int missions, Path report, Path decisionLog,
            List<com.fasterxml.jackson.databind.JsonNode> skillsPushed, List<RequirementResult> requirements) {
    }

    private final Path ioJson;
    private final Path tree;
    private final Scenario scenario;
    private final SkillTable skills;
    private final Path outDir;
    private final Endpoints endpoints;
    private final PrintWriter out;
    private double timeScale = 1.0;
    private String backend;
    private long settleMs = 1500;
    private CompiledModel roqme;
    private long periodMs = 1000;
    private ModelNames names = ModelNames.none();
    private Integer monitorPort;
    private Integer grootPort;
    private Integer monitorGrootPort;
    private Path btcppRunner;
    private Path record;
    private LiveWorld world;
    private long worldMs;
    private RequirementModel requirements;

    public Demo(Path ioJson, Path tree, Scenario scenario, SkillTable skills, Path outDir, Endpoints endpoints,
            PrintWriter out) {
        this.ioJson = ioJson;
        this.tree = tree;
        this.scenario = scenario;
        this.skills = skills;
        this.outDir = outDir;
        this.endpoints = endpoints;
        this.out = out;
    }

    /**
     * Runs closed-loop on this world (its skills, processes and contexts) for {@code durationMs} of
     * world time instead of playing the scenario; the world runs at the demo's time scale.
     */
    public Demo world(LiveWorld liveWorld, long durationMs) {
        this.world = liveWorld;
        this.worldMs = durationMs;
        return this;
    }

    /** Plays the scenario faster (0.5) or slower (2.0); the skills keep their durations. */
    public Demo timeScale(double scale) {
        this.timeScale = scale;
        return this;
    }

    /**
     * Runs the RoQME provider on this model (null: none, the scenario's estimates are the metrics),
     * ticking every periodMs of scenario time: its clock is scaled with the scenario's.
     */
    public Demo provider(CompiledModel model, long periodMs) {
        this.roqme = model;
        this.periodMs = periodMs;
        return this;
    }

    /**
     * Checks these requirements live beside the engine (null: none), on world time: each event is
     * told as it happens, each verdict at the end, and the report shows the violations.
     */
    public Demo requirements(RequirementModel model) {
        this.requirements = model;
        return this;
    }

    /** The engine's backend by name (null: the engine's default). */
    public Demo backend(String name) {
        this.backend = name;
        return this;
    }

    /** How the model names its inputs, for the report and the live page. */
    public Demo names(ModelNames modelNames) {
        this.names = modelNames;
        return this;
    }

    /** Groot2's ports could not be bound. */
    public static final class GrootBindException extends RuntimeException {
        GrootBindException(String message) {
            super(message);
        }
    }

    /** Serves Groot2's protocol for the running tree on 127.0.0.1:port and port + 1 (null: none). */
    public Demo groot(Integer port) {
        this.grootPort = port;
        return this;
    }

    /** The Groot2 server the live page debugs through (null: none; usually the executor's, {@link #groot}). */
    public Demo monitorGroot(Integer port) {
        this.monitorGrootPort = port;
        return this;
    }

    /**
     * Records the run into this .btlog (FileLogger2's format, written by either executor) and the
     * bus beside it ({@link Btlog#busLogOf}); null: no recording.
     */
    public Demo record(Path btlog) {
        this.record = btlog;
        return this;
    }

    /** Serves the live monitor page on 127.0.0.1:port while the demo runs (null: none). */
    public Demo monitor(Integer port) {
        this.monitorPort = port;
        return this;
    }

    /**
     * Runs the tree on BehaviorTree.CPP 4 through this miron-btcpp-run (cpp/miron_btcpp) instead of
     * the Java executor (null: the Java executor). The tree must be a version-4 tree.
     */
    public Demo btcpp(Path runner) {
        this.btcppRunner = runner;
        return this;
    }

    public Result run() throws EngineStartException, InterruptedException, java.io.IOException {
        Path decisionLog = outDir.resolve("decisions.jsonl");
        EngineOptions options = new EngineOptions(ioJson).endpoints(endpoints);
        options.decisionLog = decisionLog;
        options.backend = backend;
        try (Broker broker = new Broker(endpoints).start();
                SkillInterfaceMock skillInterface = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(),
                        world != null ? world : new TableSkills(skills)).start();
                Engine engine = Engine.create(options);
                LiveProvider provider = roqme == null ? null
                        : new LiveProvider(roqme, periodMs, 5000, endpoints.busIn(), endpoints.busOut()).timeScale(timeScale);
                MonitorServer monitor = monitorPort == null ? null
                        : LiveMonitor.start(monitorPort, tree, endpoints, names::qualified)) {
            if (monitor != null) {
                out.println("MIRoN demo: live monitor on " + monitor.url() + " (open it in a browser)");
                if (monitorGrootPort != null) {
                    monitor.attachGroot(monitorGrootPort);
                    out.println("MIRoN demo: the live monitor debugs through Groot2 on 127.0.0.1:" + monitorGrootPort);
                }
            }
            Narrator narrator = new Narrator(out, engine.model());
            try (BusLog busLog = record == null ? null : BusLog.start(Btlog.busLogOf(record), endpoints.busIn(), endpoints.busOut());
                    BusRecorder recorder = new BusRecorder(endpoints.busIn(), endpoints.busOut(), narrator::onBusEvent)
                    .start();
                    ScenarioPlayer player = world != null ? null : new ScenarioPlayer(scenario, timeScale, endpoints.busIn())) {
                narrator.setClock(recorder);
                int missionCount;
                List<RequirementResult> verdicts = List.of();
                try (DemoRequirements checks = requirements == null ? null
                        : DemoRequirements.start(requirements, endpoints, recorder, timeScale, narrator)) {
                    missionCount = btcppRunner != null
                            ? runOnBtcpp(engine, provider, narrator, recorder, player)
                            : runOnJava(engine, provider, narrator, recorder, player);
                    if (checks != null) {
                        verdicts = checks.finish();
                        awaitFinalStatus(recorder);
                    }
                }
                TimelineReport timeline = new TimelineReport("MIRoN demo: " + engine.model().model(), recorder.events(),
                        recorder.elapsed(), names).requirementTimeScale(timeScale);
                TreeSnapshots trees = TreeSnapshots.of(tree, ioJson);
                if (trees != null) {
                    timeline.section(trees.html(recorder.events()));
                }
                SkillTimeline skillRuns = new SkillTimeline(recorder.events(), recorder.elapsed());
                if (!skillRuns.isEmpty()) {
                    timeline.section(skillRuns.html());
                }
                Path report = timeline.write(outDir.resolve("report.html"));
                int adaptations = (int) recorder.events().stream().filter(e -> e.topic().equals("miron.decision"))
                        .mapToLong(e -> e.body().path("changed").size()).sum();
                return new Result(adaptations, skillInterface.history().size(), missionCount, report, decisionLog,
                        skillInterface.pushed(), verdicts);
            }
        }
    }

    /** The report reads the requirement events from the recorder: wait (2 s at most) until their last one came. */
    private static void awaitFinalStatus(BusRecorder recorder) throws InterruptedException {
        long end = System.currentTimeMillis() + 2000;
        while (System.currentTimeMillis() < end && recorder.events().stream().noneMatch(e -> e.topic()
                .equals(Topics.REQUIREMENT_STATUS) && e.body().path("state").asText().equals("finished"))) {
            Thread.sleep(20);
        }
    }

    private int runOnJava(Engine engine, LiveProvider provider, Narrator narrator, BusRecorder recorder,
            ScenarioPlayer player) throws InterruptedException, EngineStartException, java.io.IOException {
        AtomicInteger missions = new AtomicInteger();
        AtomicBoolean scenarioOver = new AtomicBoolean();
        try (LiveExecutor executor = new LiveExecutor(endpoints).build(tree, narrator)) {
            if (record != null) {
                executor.record(record);
                out.println("MIRoN demo: recording the tree into " + record + ", the bus into " + Btlog.busLogOf(record));
            }
            if (grootPort != null) {
                try {
                    executor.serveGroot(grootPort);
                } catch (RuntimeException e) {
                    throw new GrootBindException("cannot serve Groot2 on 127.0.0.1:" + grootPort + ": " + e.getMessage());
                }
                out.println("MIRoN demo: Groot2 can connect to 127.0.0.1:" + grootPort + " (and " + (grootPort + 1) + ")");
            }
            out.println("MIRoN demo: the behaviour tree " + tree.getFileName() + " runs as BehaviorTree.CPP "
                    + executor.tree().formatVersion() + "; the engine decides with the " + engine.backendName()
                    + " backend.");
            startProviderAndEngine(engine, provider);
            Thread robot = new Thread(() -> {
                while (!scenarioOver.get()) {
                    NodeStatus status = executor.run(Duration.ofMillis(50));
                    if (status == NodeStatus.RUNNING) {
                        break; // stopped
                    }
                    missions.incrementAndGet();
                    narrator.say(recorder.elapsed(), "ROBOT ", "mission " + status + (scenarioOver.get() ? "" : ", starting again"));
                }
            }, "demo-robot");
            robot.start();
            play(player);
            Thread.sleep(settleMs);
            scenarioOver.set(true);
            executor.stop();
            robot.join(5000);
        }
        return missions.get();
    }

    private int runOnBtcpp(Engine engine, LiveProvider provider, Narrator narrator, BusRecorder recorder,
            ScenarioPlayer player) throws InterruptedException, java.io.IOException, EngineStartException {
        try (BtcppExecutor executor = new BtcppExecutor(btcppRunner, tree, endpoints, narrator, recorder)) {
            if (record != null) {
                executor.record(record); // BehaviorTree.CPP's own FileLogger2
                out.println("MIRoN demo: recording the tree into " + record + " (FileLogger2), the bus into " + Btlog.busLogOf(record));
            }
            if (grootPort != null) {
                executor.groot(grootPort); // BehaviorTree.CPP's own Groot2Publisher
                out.println("MIRoN demo: Groot2 can connect to 127.0.0.1:" + grootPort + " (and " + (grootPort + 1) + ")");
            }
            out.println("MIRoN demo: the behaviour tree " + tree.getFileName() + " runs on the real BehaviorTree.CPP 4 "
                    + "(miron-btcpp-run with the MIRoN plugin); the engine decides with the " + engine.backendName()
                    + " backend.");
            startProviderAndEngine(engine, provider);
            executor.start();
            play(player);
            Thread.sleep(settleMs);
            return executor.stop();
        }
    }

    /** The scenario to its end, or the world for its duration (it started with the first skill pushed, if not before). */
    private void play(ScenarioPlayer player) throws InterruptedException {
        if (world == null) {
            player.play(10_000);
            return;
        }
        // The world's clock starts with the first skill the robot pushes, not before: a cold JVM
        // takes a second or two to get that push through, and the robot would sit docked,
        // charging, meanwhile, so that the story would depend on the machine. At the latest after 10 s.
        if (!world.awaitStarted(10_000)) {
            world.begin();
        }
        Thread.sleep(Math.round(worldMs * timeScale));
    }

    private void startProviderAndEngine(Engine engine, LiveProvider provider) throws InterruptedException, EngineStartException {
        if (provider != null) {
            out.println("MIRoN demo: the RoQME provider computes " + String.join(", ", properties())
                    + " from the RoQME part of " + roqme.model().source() + " every " + periodMs + " ms of "
                    + (world != null ? "world" : "scenario") + " time.");
            provider.start();
            if (!provider.awaitSubscribed(10_000)) {
                throw new IllegalStateException("the RoQME provider did not connect to the bus within 10 s");
            }
        }
        engine.start();
    }

    private List<String> properties() {
        return roqme.model().beliefs().stream().filter(b -> b.isProperty()).map(b -> b.name()).toList();
    }
}
