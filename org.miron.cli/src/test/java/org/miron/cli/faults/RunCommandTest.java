package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.BusProbe;

/**
 * {@code miron run} as a real process on free loopback ports, a Java peer on its bus: the robot's
 * contexts in, the provider's estimates, the monitors' status and the engine's decisions out;
 * SIGTERM as its help says; a busy endpoint and a model with errors refused before anything runs.
 */
public class RunCommandTest {
    private static final long TIMEOUT = 60_000;
    private static final String MODEL = RepositoryRoot.resolve("examples/intralogistics/intralogistics.miron").toString();
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();

    private String[] args(String... extra) {
        List<String> a = new ArrayList<>(List.of("run", MODEL, "--request", ep.request(), "--skill", ep.skill(),
                "--bus-in", ep.busIn(), "--bus-out", ep.busOut(),
                "--decision-log", tmp.getRoot().toPath().resolve("decisions.jsonl").toString(),
                "--model-cache", tmp.getRoot().toPath().resolve("cache").toString()));
        a.addAll(List.of(extra));
        return a.toArray(String[]::new);
    }

    private static int documentedSigterm() {
        String help = MironCli.commandLine().getSubcommands().get("run").getUsageMessage();
        java.util.regex.Matcher m = Pattern.compile("(?m)^\\s*(\\d+)\\s+.*SIGTERM").matcher(help);
        assertTrue(help, m.find());
        return Integer.parseInt(m.group(1));
    }

    /** Established loopback TCP connections to the endpoint's port, from /proc/net/tcp (IPv4 and IPv6). */
    private static int connectionsTo(String endpoint) throws java.io.IOException {
        int port = URI.create(endpoint.replace("tcp://", "http://")).getPort();
        int n = 0;
        for (String table : List.of("/proc/net/tcp", "/proc/net/tcp6")) {
            Path f = Path.of(table);
            if (!Files.exists(f)) {
                continue;
            }
            for (String line : Files.readAllLines(f)) {
                String[] c = line.trim().split("\\s+");
                // sl local_address rem_address st ...: the remote side is the broker's port, st 01 is ESTABLISHED
                if (c.length > 3 && c[2].contains(":") && c[3].equals("01")
                        && Integer.parseInt(c[2].substring(c[2].indexOf(':') + 1), 16) == port) {
                    n++;
                }
            }
        }
        return n;
    }

    private static String context(String name, String type, Object value) {
        return "{\"name\":\"" + name + "\",\"namespace\":\"Intralogistics\",\"type\":\"" + type + "\",\"value\":" + value + "}";
    }

    @Test
    public void runsProviderMonitorsAndEngineInOneProcessAndStopsOnSigterm() throws Exception {
        Path dir = tmp.getRoot().toPath();
        try (RuntimeProcess p = RuntimeProcess.start(dir, "run", args("--period", "200"))) {
            assertTrue(p.output(), p.awaitOutput("miron run: running intralogistics.miron", TIMEOUT));
            String out = p.output();
            for (String line : new String[] { "miron run: broker: requests " + ep.request() + " -> skill interface " + ep.skill()
                    + ", bus " + ep.busIn() + " -> " + ep.busOut(), "miron run: requirements: 5 monitored",
                    "miron run: roqme provider: model intralogistics", "miron run: engine: model intralogistics, backend native, "
                            + "bus in process (no sockets to the broker)" }) {
                assertTrue(line + " in:\n" + out, out.contains(line));
            }
            // The provider, the monitors and the engine are running and reach the broker without
            // sockets: nothing is connected to its bus ports yet (separate components would hold
            // four connections to bus-in and three to bus-out).
            assertEquals(out, 0, connectionsTo(ep.busIn()) + connectionsTo(ep.busOut()));
            try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.", "miron.");
                    BusClient robot = new BusClient("test-robot", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
                assertTrue(robot.awaitReady(TIMEOUT));
                // the engine's first decision, from the broker's cache
                assertNotNull(p.output(), probe.await(Topics.VARIANT_PREFIX + "task", b -> b.path("varpoint").asText().equals("task"), TIMEOUT));
                long end = System.currentTimeMillis() + TIMEOUT;
                JsonNode estimate = null;
                while (estimate == null && System.currentTimeMillis() < end) {
                    robot.publish(Topics.CONTEXT, context("BatteryLevel", "number", 5));
                    robot.publish(Topics.CONTEXT, context("HumanDistance", "number", 0.8));
                    estimate = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy"), 300);
                }
                assertNotNull("the provider's estimates:\n" + p.output(), estimate);
                assertNotNull("the requirement monitors' status:\n" + p.output(), probe.await(Topics.REQUIREMENT_STATUS,
                        b -> b.path("counters").path("contextsIn").asLong() > 0, TIMEOUT));
                assertTrue(p.output(), p.isAlive());
            }
            assertEquals(p.output(), documentedSigterm(), p.terminate(TIMEOUT));
            assertFalse(p.output(), p.output().contains("Exception"));
        }
    }

    /** Without the provider, estimates from elsewhere drive the engine: power_autonomy below 0.3 docks the robot. */
    @Test
    public void withoutProviderTheEstimatesFromElsewhereDecide() throws Exception {
        Path dir = tmp.getRoot().toPath();
        try (RuntimeProcess p = RuntimeProcess.start(dir, "run", args("--no-provider"))) {
            assertTrue(p.output(), p.awaitOutput("miron run: running intralogistics.miron", TIMEOUT));
            assertTrue(p.output(), p.output().contains("miron run: roqme provider: not run"));
            try (BusProbe probe = new BusProbe(ep.busOut(), Topics.VARIANT_PREFIX);
                    BusClient roqme = new BusClient("test-roqme", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
                assertTrue(roqme.awaitReady(TIMEOUT));
                long end = System.currentTimeMillis() + TIMEOUT;
                JsonNode dock = null;
                while (dock == null && System.currentTimeMillis() < end) {
                    roqme.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.1}");
                    dock = probe.await(Topics.VARIANT_PREFIX + "task", b -> b.path("value").asText().equals("dock"), 300);
                }
                assertNotNull("task = dock:\n" + p.output(), dock);
            }
            assertEquals(p.output(), documentedSigterm(), p.terminate(TIMEOUT));
        }
    }

    /**
     * Inside the one process each component still counts and drops what it cannot read: a
     * malformed estimate (engine, monitors) and a malformed context (provider, monitors) are
     * counted on their statuses, the process lives, and the next good estimate decides.
     */
    @Test
    public void malformedMessagesAreCountedByEachComponentAndDropped() throws Exception {
        try (RuntimeProcess p = RuntimeProcess.start(tmp.getRoot().toPath(), "run", args("--period", "200",
                "--status-interval", "200"))) {
            assertTrue(p.output(), p.awaitOutput("miron run: running intralogistics.miron", TIMEOUT));
            try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.status", "miron.");
                    BusClient robot = new BusClient("test-robot", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
                assertTrue(robot.awaitReady(TIMEOUT));
                assertNotNull(probe.await(Topics.VARIANT_PREFIX + "task", b -> true, TIMEOUT));
                robot.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"value\":");
                robot.publish(Topics.CONTEXT, "{\"name\":");
                assertNotNull("engine:\n" + p.output(), probe.await(Topics.STATUS,
                        b -> b.path("counters").path("malformedInput").asLong() >= 1, TIMEOUT));
                assertNotNull("provider:\n" + p.output(), probe.await(Topics.ROQME_STATUS,
                        b -> b.path("counters").path("malformedInput").asLong() >= 1, TIMEOUT));
                assertNotNull("monitors:\n" + p.output(), probe.await(Topics.REQUIREMENT_STATUS,
                        b -> b.path("counters").path("badBusInput").asLong() >= 2, TIMEOUT));
                JsonNode dock = null;
                for (long end = System.currentTimeMillis() + TIMEOUT; dock == null && System.currentTimeMillis() < end;) {
                    robot.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.05}");
                    dock = probe.await(Topics.VARIANT_PREFIX + "task", b -> b.path("value").asText().equals("dock"), 300);
                }
                assertNotNull("a good estimate still decides:\n" + p.output(), dock);
                assertTrue(p.output(), p.isAlive());
            }
            assertEquals(p.output(), documentedSigterm(), p.terminate(TIMEOUT));
        }
    }

    /** A solver that fails is retried inside the one process as in the separate engine: the status counts it, a decision follows. */
    @Test
    public void aFailingSolverIsRetried() throws Exception {
        Path dir = tmp.getRoot().toPath();
        Path marker = dir.resolve("failed-once");
        Path flaky = dir.resolve("flaky-minizinc");
        Files.writeString(flaky, "#!/bin/sh\n"
                + "# fails the first solve, then is the real minizinc\n"
                + "case \"$*\" in *--version*) exec minizinc \"$@\";; esac\n"
                + "if [ ! -e '" + marker + "' ]; then touch '" + marker + "'; echo 'solver crashed' >&2; exit 1; fi\n"
                + "exec minizinc \"$@\"\n");
        assertTrue(flaky.toFile().setExecutable(true));
        try (RuntimeProcess p = RuntimeProcess.start(dir, "run", args("--no-provider", "--backend", "minizinc",
                "--minizinc", flaky.toString()))) {
            assertTrue(p.output(), p.awaitOutput("miron run: running intralogistics.miron", TIMEOUT));
            try (BusProbe probe = new BusProbe(ep.busOut(), "miron.")) {
                assertNotNull("a retry after the failed solve:\n" + p.output(), probe.await(Topics.STATUS,
                        b -> b.path("counters").path("solveRetries").asLong() >= 1, TIMEOUT));
                assertNotNull("then a decision:\n" + p.output(), probe.await(Topics.DECISION, b -> true, TIMEOUT));
                assertTrue(Files.exists(marker));
            }
            assertEquals(p.output(), documentedSigterm(), p.terminate(TIMEOUT));
        }
    }

    /**
     * The robot's process holds no language tooling: the model is generated in a JVM of its own,
     * then kept; a restart with nothing changed starts from what was kept, and a change to a file
     * the model imports generates it again.
     */
    @Test
    public void theGenerationIsKeptWhileTheModelAndItsImportsAreUnchanged() throws Exception {
        Path dir = tmp.getRoot().toPath();
        Path copy = dir.resolve("model");
        Files.createDirectories(copy);
        for (String f : List.of("intralogistics.miron", "intralogistics.bt", "intralogistics.roqme")) {
            Files.copy(RepositoryRoot.resolve("examples/intralogistics/" + f), copy.resolve(f));
        }
        String[] run = args("--no-provider");
        run[1] = copy.resolve("intralogistics.miron").toString();
        String[] outputs = new String[3];
        for (int i = 0; i < 3; i++) {
            if (i == 2) { // the imported tree changes (a comment): generated again
                Files.writeString(copy.resolve("intralogistics.bt"), "\n<!-- changed -->\n", java.nio.file.StandardOpenOption.APPEND);
            }
            try (RuntimeProcess p = RuntimeProcess.start(dir, "run", run)) {
                assertTrue(p.output(), p.awaitOutput("miron run: running intralogistics.miron", TIMEOUT));
                outputs[i] = p.output();
                if (i < 2) { // generated in a JVM of its own, or kept
                    String classes = loadedClasses(p.pid());
                    assertTrue(classes, classes.contains("org.miron.runtime.engine.Engine"));
                    for (String tooling : List.of("org.eclipse.xtext.", "org.eclipse.emf.", "com.google.inject.")) {
                        assertFalse(tooling + " loaded in the robot's process", classes.contains(tooling));
                    }
                }
                assertEquals(p.output(), documentedSigterm(), p.terminate(TIMEOUT));
            }
        }
        assertTrue(outputs[0], outputs[0].contains("miron run: model intralogistics.miron: generated in "));
        assertTrue(outputs[1], outputs[1].contains("miron run: model intralogistics.miron: unchanged since it was generated into "));
        assertTrue(outputs[2], outputs[2].contains("miron run: model intralogistics.miron: generated in "));
    }

    /** Every class the JVM has loaded, by the JDK's own jcmd. */
    private static String loadedClasses(long pid) throws Exception {
        Process jcmd = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "jcmd").toString(),
                Long.toString(pid), "VM.class_hierarchy").redirectErrorStream(true).start();
        String out = new String(jcmd.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(out, 0, jcmd.waitFor());
        return out;
    }

    @Test
    public void aBusyEndpointIsExit2NamingItAndNothingRuns() throws Exception {
        int port = URI.create(ep.busOut().replace("tcp://", "http://")).getPort();
        try (ServerSocket busy = new ServerSocket(port, 1, InetAddress.getLoopbackAddress());
                RuntimeProcess p = RuntimeProcess.start(tmp.getRoot().toPath(), "run", args())) {
            assertEquals(p.output(), 2, p.awaitExit(TIMEOUT));
            assertTrue(p.output(), p.output().contains("miron run: error: broker cannot bind its endpoints: " + ep.busOut()));
            assertFalse(p.output(), p.output().contains("miron run: engine:"));
        }
    }

    @Test
    public void aModelWithErrorsIsExit1WithFileLineCol() throws Exception {
        Path dir = tmp.newFolder("model").toPath();
        Path examples = RepositoryRoot.resolve("examples/intralogistics");
        for (String f : new String[] { "intralogistics.bt", "intralogistics.roqme" }) {
            Files.copy(examples.resolve(f), dir.resolve(f));
        }
        Path model = dir.resolve("intralogistics.miron");
        Files.writeString(model, Files.readString(examples.resolve("intralogistics.miron"))
                .replace("implies task = task::dock", "implies task = task::nowhere"));
        List<String> a = new ArrayList<>(List.of(args()));
        a.set(1, model.toString());
        try (RuntimeProcess p = RuntimeProcess.start(tmp.getRoot().toPath(), "run", a.toArray(String[]::new))) {
            assertEquals(p.output(), 1, p.awaitExit(TIMEOUT));
            assertTrue(p.output(), Pattern.compile("(?m)^" + Pattern.quote(model.toString()) + ":\\d+:\\d+: error").matcher(p.output()).find());
            assertFalse(p.output(), p.output().contains("miron run: broker:"));
        }
    }
}
