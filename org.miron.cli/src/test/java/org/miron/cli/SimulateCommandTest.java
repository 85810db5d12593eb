package org.miron.cli;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Json;

/**
 * `miron simulate` on the intralogistics example and its world: the same seed writes the same
 * bytes, in this JVM and in another one (nothing depends on hashing, threads or the wall clock);
 * the summary has every policy's measures with intervals; a bad world is refused before anything runs.
 */
public class SimulateCommandTest {
    private static final Path MODEL = Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron");
    private static final Path WORLD = Cli.ROOT.resolve("examples/intralogistics/world.json");

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static String[] args(Path out, String seed) {
        return new String[] { "simulate", MODEL.toString(), "--world", WORLD.toString(), "--duration", "20m", "--runs", "3",
            "--seed", seed, "--policy", "adaptive", "--policy", "preset", "--policy", "fixed:maxVelocity=10", "--out", out.toString(),
            "--timeline", "5m" };
    }

    @Test
    public void theSameSeedWritesTheSameBytesInAnyJvm() throws Exception {
        Path a = tmp.getRoot().toPath().resolve("a");
        Path b = tmp.getRoot().toPath().resolve("b");
        Cli first = new Cli();
        assertEquals(first.err.toString(), 0, first.run(args(a, "5")));
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), MironCli.class.getName()));
        command.addAll(List.of(args(b, "5")));
        Process other = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(tmp.getRoot().toPath().resolve("other.log").toFile()).start();
        other.getOutputStream().close();
        assertTrue("the second JVM did not finish in 10 minutes", other.waitFor(10, TimeUnit.MINUTES));
        assertEquals(Files.readString(tmp.getRoot().toPath().resolve("other.log")), 0, other.exitValue());
        for (String file : List.of("summary.json", "report.html")) {
            assertArrayEquals(file, Files.readAllBytes(a.resolve(file)), Files.readAllBytes(b.resolve(file)));
        }
        JsonNode summary = Json.MAPPER.readTree(a.resolve("summary.json").toFile());
        for (String policy : List.of("adaptive", "preset", "fixed:maxVelocity=10")) {
            JsonNode deliveries = summary.path("policies").path(policy).path("deliveries");
            assertEquals(policy + ": " + deliveries, 3, deliveries.path("runs").size());
            double mean = deliveries.path("mean").asDouble();
            assertTrue(deliveries.toString(), deliveries.path("ci95").get(0).asDouble() <= mean && mean <= deliveries.path("ci95").get(1).asDouble());
            assertTrue(summary.path("policies").path(policy).has("metric:safety"));
        }
        String report = Files.readString(a.resolve("report.html"));
        assertTrue(report.contains("<h2>Policy adaptive: the first 5 min of run 1</h2>"));
        assertTrue("the bar charts show every measure", report.contains(">near_misses</text>") || report.contains(">near_misses ("));
        assertTrue(first.out().contains("fast_near_person"));
        Cli other5 = new Cli();
        other5.run(args(tmp.getRoot().toPath().resolve("c"), "6"));
        assertFalse("another seed, another summary", Files.readString(tmp.getRoot().toPath().resolve("c/summary.json"))
                .equals(Files.readString(a.resolve("summary.json"))));
    }

    /** The Nav2-shaped example (examples/nav2) passes miron check and simulates: the adaptive robot adapts and reaches goals. */
    @Test
    public void theNav2ExampleChecksAndSimulates() throws Exception {
        Path dir = Cli.ROOT.resolve("examples/nav2");
        Cli check = new Cli();
        assertEquals(check.err.toString() + check.out(), 0, check.run("check", dir.resolve("nav2.miron").toString(),
                dir.resolve("nav2.bt").toString(), dir.resolve("nav2.roqme").toString()));
        Path out = tmp.getRoot().toPath().resolve("nav2");
        Cli sim = new Cli();
        assertEquals(sim.err.toString(), 0, sim.run("simulate", dir.resolve("nav2.miron").toString(), "--world",
                dir.resolve("world.json").toString(), "--duration", "1h", "--runs", "2", "--out", out.toString()));
        JsonNode policies = Json.MAPPER.readTree(out.resolve("summary.json").toFile()).path("policies");
        assertTrue(policies.toString(), policies.path("adaptive").path("engine:adaptations").path("mean").asDouble() > 0);
        for (String policy : List.of("adaptive", "preset")) {
            assertTrue(policy, policies.path(policy).path("goals").path("mean").asDouble() > 0);
        }
        assertTrue("slowing near people: fewer near misses", policies.path("adaptive").path("near_misses").path("mean").asDouble()
                < policies.path("preset").path("near_misses").path("mean").asDouble());
    }

    @Test
    public void aBadWorldIsRefusedWithItsPositions() throws Exception {
        String bad = Files.readString(WORLD).replace("\"FreeSpace\": { \"value\": \"freeSpace\" }",
                "\"FreeSpace\": { \"value\": \"freeSpace == 'HIHG'\" }");
        Path world = Cli.write(tmp.getRoot().toPath(), "bad/world.json", bad);
        Path out = tmp.getRoot().toPath().resolve("out");
        Cli cli = new Cli();
        assertEquals(1, cli.run("simulate", MODEL.toString(), "--world", world.toString(), "--out", out.toString()));
        assertTrue(cli.err.toString(), cli.err.toString().matches("(?s).*world\\.json:\\d+:\\d+: error \\[world\\.type\\]: .*'HIHG'.*"
                + "\\(at /contexts/FreeSpace/value\\).*"));
        assertFalse("nothing simulated", Files.exists(out.resolve("summary.json")));
    }

    @Test
    public void aPolicyNamingNoVarpointIsAUsageError() {
        Cli cli = new Cli();
        assertEquals(2, cli.run("simulate", MODEL.toString(), "--world", WORLD.toString(), "--policy", "fixed:speed=10",
                "--out", tmp.getRoot().toString()));
        assertTrue(cli.err.toString(), cli.err.toString().contains("no varpoint 'speed'"));
        assertEquals(2, new Cli().run("simulate", MODEL.toString(), "--world", WORLD.toString(), "--policy", "fast"));
    }

    /**
     * --coverage on the example (issue 36, item 4): a line per tree node, variant and rule, a column
     * per policy, the summary's coverage object, the report's table; --min-coverage exits 1 for the
     * policy that falls short and names it, 0 when every policy reaches it.
     */
    @Test
    public void coverageAndItsGate() throws Exception {
        Path a = tmp.getRoot().toPath().resolve("cov");
        String[] args = { "simulate", MODEL.toString(), "--world", WORLD.toString(), "--duration", "30m", "--runs", "2", "--seed", "1",
            "--policy", "adaptive", "--policy", "fixed:task=deliver", "--out", a.toString(), "--timeline", "1m", "--coverage" };
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 0, cli.run(args));
        String o = cli.out();
        assertTrue(o, o.matches("(?s).*\ncoverage  item +adaptive +fixed:task=deliver\n.*"));
        assertTrue(o, o.matches("(?s).*\nnode      Main/monitoring_parallel +100\\.0 %  ticked \\d+, S \\d+, F \\d+ +100\\.0 %.*"));
        assertTrue(o, o.matches("(?s).*\nvariant   task::deliver +\\d+\\.\\d % +100\\.0 %\n.*"));
        assertTrue(o, o.matches("(?s).*\nrule      noBattery +\\d+\\.\\d %  \\d+ of \\d+ decisions +0\\.0 %  0 of 0 decisions\n.*"));
        assertTrue(o, o.matches("(?s).*\n +covered +\\d+ of \\d+ \\(\\d+\\.\\d %\\) +\\d+ of \\d+ \\(\\d+\\.\\d %\\)\n.*"));
        JsonNode coverage = Json.MAPPER.readTree(a.resolve("summary.json").toFile()).path("coverage");
        double adaptive = coverage.path("adaptive").path("share").asDouble();
        double deliver = coverage.path("fixed:task=deliver").path("share").asDouble(); // its branch has fewer nodes
        assertTrue(coverage.toString(), deliver < adaptive && adaptive <= 1);
        JsonNode variants = coverage.path("adaptive").path("variants");
        double time = 0;
        for (JsonNode v : variants) {
            time += v.path("heldS").asDouble();
        }
        assertEquals("task has a value all the time", 2 * 1800, time, 1e-6);
        assertTrue(Files.readString(a.resolve("report.html")).contains("<h2>Coverage</h2>"));
        args[args.length - 1] = "--min-coverage=" + 50 * (adaptive + deliver); // between the two
        Cli gated = new Cli();
        assertEquals(gated.err.toString(), 1, gated.run(args));
        assertTrue(gated.err.toString(), gated.err.toString().contains("miron simulate: coverage of fixed:task=deliver is "));
        assertFalse(gated.err.toString(), gated.err.toString().contains("coverage of adaptive"));
        args[args.length - 1] = "--min-coverage=" + (100 * deliver - 0.01);
        assertEquals(0, new Cli().run(args));
        args[args.length - 1] = "--min-coverage=101";
        assertEquals(2, new Cli().run(args));
    }
}
