package org.miron.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.ZoneId;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.io.IOException;
import org.miron.cli.monitor.LiveMonitor;
import org.miron.cli.monitor.MonitorServer;
import org.miron.executor.BtBuildException;
import org.miron.executor.NodeStatus;
import org.miron.executor.trace.ConsoleTracePrinter;
import org.miron.runtime.Endpoints;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.recording.Btlog;
import org.miron.runtime.recording.BusLog;
import org.miron.runtime.skill.SkillDeadlines;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code miron execute TREE}: runs a (woven) behaviour tree against the bus and the skill interface. */
@Command(name = "execute", mixinStandardHelpOptions = true,
        description = "Run a behaviour tree (.bt or woven .ext.xml): VariantAction nodes follow the engine's "
                + "decisions, other actions are pushed as skills to the skill interface; prints a trace.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { "0:the tree succeeded", "1:the tree failed (without --repeat)", "2:the tree cannot be loaded",
                ExitCodes.SIGTERM + " while running", ExitCodes.SIGINT + " while running" })
public final class ExecuteCommand implements Callable<Integer> {
    @Parameters(paramLabel = "TREE", description = "the tree file")
    Path treeFile;

    @Option(names = "--period", paramLabel = "MS", description = "tick period in ms (default: ${DEFAULT-VALUE})")
    long periodMs = 100;

    @Option(names = "--show-resets", description = "also trace the reset of finished nodes to IDLE")
    boolean showResets;

    @Mixin
    BrokerEndpoints.Request request = new BrokerEndpoints.Request();

    @Option(names = "--skill-events", description = "skill interface PUB with skill results (default: ${DEFAULT-VALUE})")
    String skillEvents = Endpoints.DEFAULT_SKILL_EVENTS;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Mixin
    BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

    @Option(names = "--skill-deadline", paramLabel = "SKILL=MS",
            description = "result deadline of a pushed skill (repeatable; * for the others; default 120000): "
                    + "without a result by then the node fails and the skill is aborted")
    Map<String, Long> skillDeadlines = new LinkedHashMap<>();

    @Option(names = "--repeat", description = "run the tree again each time it finishes, as a robot on a round of "
            + "missions (and the demo) does, until stopped")
    boolean repeat;

    @Option(names = "--monitor", paramLabel = "PORT",
            description = "serve the live monitor page (the tree coloured by node status, the variation points and "
                    + "metrics) on http://127.0.0.1:PORT/ while the tree runs (docs/diagrams.md)")
    Integer monitorPort;

    @Option(names = "--groot", paramLabel = "PORT",
            description = "serve Groot2's protocol for the tree on 127.0.0.1:PORT and PORT+1, as BehaviorTree.CPP 4's "
                    + "Groot2Publisher does: the tree with uids, statuses, blackboards, breakpoints (docs/bt-semantics.md, \"Groot2\")")
    Integer grootPort;

    @Option(names = "--monitor-groot", paramLabel = "PORT",
            description = "the Groot2 server on 127.0.0.1 the live page debugs through (breakpoints, forced results, "
                    + "blackboards): another executor's, e.g. miron-btcpp-run --groot PORT; default: --groot's PORT")
    Integer monitorGrootPort;
    @Option(names = "--record", paramLabel = "FILE.btlog",
            description = "record the run as BehaviorTree.CPP's FileLogger2 does (what Groot2 and `miron replay` open), "
                    + "and the bus beside it in FILE.bus.jsonl (docs/diagrams.md, \"Recording and replay\")")
    Path record;

    @Override
    public Integer call() {
        if (!Files.isRegularFile(treeFile)) {
            System.err.println(treeFile + ": error: no such file");
            return 2;
        }
        if (record != null) {
            try {
                Btlog.checkExtension(record);
            } catch (IllegalArgumentException e) {
                System.err.println("miron execute: error: " + e.getMessage());
                return 2;
            }
        }
        Endpoints endpoints = new Endpoints(request.endpoint, Endpoints.DEFAULT_SKILL, skillEvents, busIn.endpoint, busOut.endpoint);
        MonitorServer monitor = null;
        if (monitorPort != null) {
            try {
                monitor = LiveMonitor.start(monitorPort, treeFile, endpoints, LiveMonitor.plainNames());
            } catch (IOException | RuntimeException e) {
                System.err.println("miron execute: error: cannot serve the monitor on 127.0.0.1:" + monitorPort + ": " + e.getMessage());
                return 2;
            }
            System.out.println("live monitor: " + monitor.url());
            Integer debugPort = monitorGrootPort != null ? monitorGrootPort : grootPort;
            if (debugPort != null) {
                if (debugPort < 1 || debugPort > 65534) {
                    System.err.println("miron execute: error: the Groot2 port must be 1 to 65534 (it uses the next one too): " + debugPort);
                    monitor.close();
                    return 2;
                }
                monitor.attachGroot(debugPort);
                System.out.println("live monitor: debugs through Groot2 on 127.0.0.1:" + debugPort);
            }
        }
        BusLog busLog = null;
        if (record != null) {
            try {
                busLog = BusLog.start(Btlog.busLogOf(record), endpoints.busIn(), endpoints.busOut());
            } catch (IOException e) {
                System.err.println("miron execute: error: cannot record into " + Btlog.busLogOf(record) + ": " + e.getMessage());
                return 2;
            }
        }
        try (BusLog bus = busLog; MonitorServer page = monitor; LiveExecutor executor = new LiveExecutor(endpoints)) {
            try {
                executor.skillDeadlines(new SkillDeadlines(skillDeadlines));
            } catch (IllegalArgumentException e) {
                System.err.println("miron execute: error: " + e.getMessage());
                return 2;
            }
            try {
                executor.build(treeFile, new ConsoleTracePrinter(System.out, ZoneId.systemDefault(), showResets));
            } catch (BtBuildException e) {
                System.err.println("miron execute: error: " + e.getMessage());
                return 2;
            }
            if (record != null) {
                try {
                    executor.record(record);
                } catch (IOException e) {
                    System.err.println("miron execute: error: cannot record into " + record + ": " + e.getMessage());
                    return 2;
                }
                System.out.println("recording: " + record + " (bus: " + Btlog.busLogOf(record) + ")");
            }
            if (grootPort != null) {
                try {
                    executor.serveGroot(grootPort);
                } catch (RuntimeException e) {
                    System.err.println("miron execute: error: cannot serve Groot2 on 127.0.0.1:" + grootPort + ": " + e.getMessage());
                    return 2;
                }
                System.out.println("groot2: 127.0.0.1:" + grootPort + " (publisher " + (grootPort + 1) + ")");
            }
            CountDownLatch finished = new CountDownLatch(1);
            Thread hook = new Thread(() -> {
                executor.stop(); // with --repeat, a stop between two runs ends the next one
                try {
                    finished.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "miron-execute-shutdown");
            Runtime.getRuntime().addShutdownHook(hook);
            NodeStatus status;
            try {
                do {
                    status = executor.run(Duration.ofMillis(periodMs));
                    if (status != NodeStatus.RUNNING) {
                        System.out.println("tree " + executor.tree().id() + " finished: " + status
                                + (repeat ? ", starting again" : ""));
                    }
                } while (repeat && status != NodeStatus.RUNNING);
            } finally {
                finished.countDown();
            }
            // RUNNING: stopped by a signal; the JVM then exits with the signal's status (ExitCodes)
            return status == NodeStatus.SUCCESS ? 0 : status == NodeStatus.FAILURE ? 1 : 3;
        }
    }
}
