package org.miron.cli;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Json;
import org.miron.testkit.Examples;
import org.miron.testkit.JsonSchemaFile;

/**
 * `miron verify` end to end: the examples' requirements over simulated shifts, the table, the
 * counterexamples, summary.json against its schema, the same bytes for the same seed, the
 * sequential test, requirements written here (not in the examples), and the exit statuses.
 */
public class VerifyCommandTest {
    private static final Path WORLD = Cli.ROOT.resolve("examples/intralogistics/world.json");

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private Path out(String name) {
        return tmp.getRoot().toPath().resolve(name);
    }

    @Test
    public void theIntralogisticsRequirementsUnderBothPoliciesWithTheirCounterexamples() throws Exception {
        Path model = Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron");
        String[] args = { "verify", model.toString(), "--world", WORLD.toString(), "--duration", "2h", "--runs", "2", "--seed", "3",
            "--policy", "adaptive", "--policy", "preset", "--out", out("a").toString() };
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 1, cli.run(args)); // slowNearPeople is violated: the adaptation's lag
        String o = cli.out();
        assertTrue(o, o.contains("MIRoN verify: intralogistics.miron in world.json, 5 requirement(s), 2 run(s) of 2h per policy, seed 3"));
        assertTrue(o, row(o, "slowNearPeople", "adaptive").matches(".*\\s2\\s+2\\s+1\\.000 \\[0\\.158, 1\\.000\\]\\s+violated"));
        assertTrue(o, o.contains("  first counterexample: run 1 (seed 3) at "));
        assertTrue(o, row(o, "slowSoonNearPeople", "adaptive").endsWith("holds"));
        assertTrue(o, row(o, "neverStranded", "adaptive").endsWith("holds"));
        assertTrue(o, row(o, "neverStranded", "preset").endsWith("violated"));
        assertTrue(o, row(o, "docksOnLowBattery", "adaptive").endsWith("holds"));
        JsonNode summary = Json.MAPPER.readTree(out("a").resolve("summary.json").toFile());
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(summary));
        JsonNode lag = summary.path("requirements").path("slowNearPeople").path("adaptive").path("firstViolation");
        assertEquals(3, lag.path("seed").asInt());
        assertTrue(lag.toString(), lag.path("values").path("roqme.HumanDistance").asDouble() < 1.5);
        assertTrue(lag.toString(), lag.path("values").path("maxVelocity").asDouble() > 10);
        JsonNode stranded = summary.path("requirements").path("neverStranded").path("preset").path("firstViolation");
        assertTrue(stranded.toString(), stranded.path("values").path("roqme.BatteryLevel").asDouble() < 1);
        assertEquals(false, stranded.path("values").path("roqme.Docked").asBoolean(true));
        assertTrue(summary.path("policies").path("adaptive").has("deliveries")); // the measures beside
        String report = Files.readString(out("a").resolve("report.html"));
        assertTrue(report.contains("slowNearPeople under adaptive: run 1 (seed 3) violated it at "));
        assertTrue(report.contains("always (roqme.HumanDistance &lt; 1.5 implies maxVelocity &lt;= 10)"));
        // the same seed, the same bytes
        args[args.length - 1] = out("b").toString();
        assertEquals(1, new Cli().run(args));
        for (String file : List.of("summary.json", "report.html")) {
            assertArrayEquals(file, Files.readAllBytes(out("a").resolve(file)), Files.readAllBytes(out("b").resolve(file)));
        }
    }

    /** The line of the table for a requirement and a policy. */
    private static String row(String out, String requirement, String policy) {
        for (String line : out.split("\n")) {
            String[] cells = line.trim().split("\\s+");
            if (cells.length > 2 && cells[0].equals(requirement) && cells[1].equals(policy)) {
                return line.trim();
            }
        }
        throw new AssertionError("no row for " + requirement + " under " + policy + " in\n" + out);
    }

    @Test
    public void requirementsWrittenHereAreCheckedAndTheExitStatusSaysWhetherAllHold() throws Exception {
        String holding = """
                /** Never a dock call left unanswered for 10 s. */
                requirement docksQuickly : always (roqme.power_autonomy < 0.3 implies eventually within 10 seconds task = task::dock)
                requirement chargesInTheFirstTwoHours : eventually within 2 hours roqme.Docked
                """;
        // what the simulator shows: once the person has gone, safety recovers slowly and the robot stays slow
        String failing = "requirement fullSpeedWhenAlone : always (roqme.HumanDistance > 5 implies eventually within 30 seconds "
                + "maxVelocity >= 50)\n";
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 1, cli.run("verify", withRequirements(holding + failing).toString(), "--world",
                WORLD.toString(), "--duration", "2h", "--runs", "2", "--out", out("c").toString()));
        for (String name : List.of("docksQuickly", "chargesInTheFirstTwoHours")) {
            assertTrue(cli.out(), row(cli.out(), name, "adaptive").endsWith("holds"));
        }
        assertTrue(cli.out(), row(cli.out(), "fullSpeedWhenAlone", "adaptive").endsWith("violated"));
        JsonNode x = Json.MAPPER.readTree(out("c").resolve("summary.json").toFile()).path("requirements")
                .path("fullSpeedWhenAlone").path("adaptive").path("firstViolation");
        assertTrue(x.toString(), x.path("values").path("roqme.HumanDistance").asDouble() > 5);
        assertTrue(x.toString(), x.path("values").path("maxVelocity").asDouble() < 50);
        assertTrue(x.toString(), x.path("detected").asDouble() - x.path("time").asDouble() >= 30); // the window had to close
        Cli ok = new Cli();
        assertEquals(ok.out() + ok.err, 0, ok.run("verify", withRequirements(holding).toString(), "--world", WORLD.toString(),
                "--duration", "2h", "--runs", "2", "--out", out("c2").toString()));
    }

    @Test
    public void aProbabilisticRequirementIsDecidedByTheSequentialTest() throws Exception {
        Path model = withRequirements("requirement rarelyStranded : never (roqme.BatteryLevel < 1 and not roqme.Docked) "
                + "with probability >= 0.9\n");
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 1, cli.run("verify", model.toString(), "--world", WORLD.toString(), "--duration", "2h",
                "--policy", "preset", "--out", out("d").toString()));
        // every preset shift strands: Wald's bound log(19) is crossed by the third violation (log(3) each)
        assertTrue(cli.out(), row(cli.out(), "rarelyStranded", "preset").endsWith("fails (SPRT, 3 runs)"));
        JsonNode s = Json.MAPPER.readTree(out("d").resolve("summary.json").toFile()).path("requirements").path("rarelyStranded")
                .path("preset").path("sequentialTest");
        assertEquals(3, s.path("runsUsed").asInt());
        assertEquals(0.85, s.path("indifference").get(0).asDouble(), 1e-9);
    }

    /** --runs N stops a sequential test that has not decided: undecided, exit 1. */
    @Test
    public void aSequentialTestCutShortByRunsIsUndecided() throws Exception {
        Path model = withRequirements("requirement rarelyStranded : never (roqme.BatteryLevel < 1 and not roqme.Docked) "
                + "with probability >= 0.9\n");
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 1, cli.run("verify", model.toString(), "--world", WORLD.toString(), "--duration", "10m",
                "--runs", "1", "--out", out("u").toString()));
        assertTrue(cli.out(), row(cli.out(), "rarelyStranded", "adaptive").endsWith("undecided after 1 run"));
    }

    @Test
    public void usageErrorsAndAModelWithoutRequirementsAreExitTwo() throws Exception {
        Path none = withRequirements("");
        Cli cli = new Cli();
        assertEquals(2, cli.run("verify", none.toString(), "--world", WORLD.toString(), "--runs", "1", "--duration", "10m",
                "--out", out("e").toString()));
        assertTrue(cli.err.toString(), cli.err.toString().contains("the model states no requirement"));
        Path model = Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron");
        Cli both = new Cli();
        assertEquals(2, both.run("verify", model.toString(), "--world", WORLD.toString(), "--runs", "3", "--confidence", "0.9"));
        assertTrue(both.err.toString(), both.err.toString().contains("--runs and --confidence exclude each other"));
        Cli bounded = new Cli(); // --max-runs bounds a sequential check only: with --runs it would be ignored
        assertEquals(2, bounded.run("verify", model.toString(), "--world", WORLD.toString(), "--runs", "3", "--max-runs", "5"));
        assertTrue(bounded.err.toString(), bounded.err.toString().contains("--runs and --max-runs exclude each other"));
        Path bad = withRequirements("requirement late : always within 0 seconds roqme.Docked with probability >= 1.5\n");
        Cli wrong = new Cli();
        assertEquals(2, wrong.run("verify", bad.toString(), "--world", WORLD.toString(), "--out", out("f").toString()));
        assertTrue(wrong.err.toString(), wrong.err.toString().contains("error [miron.requirement-"));
    }

    /** A context the world never publishes: never evaluated, said with the signal, not an error, and exit 1. */
    @Test
    public void aRequirementOverASignalThatNeverArrivesIsNeverEvaluated() throws Exception {
        Path model = withRequirements("requirement lidarClear : always (roqme.Lidar > 1 or roqme.Docked)\n"
                + "requirement docks : eventually within 2 hours roqme.Docked\n"
                + "requirement overfull : eventually roqme.BatteryLevel > 100\n"); // no witness by the end: open, not violated
        Path roqme = model.resolveSibling("intralogistics.roqme");
        Files.writeString(roqme, Files.readString(roqme) + "\ncontext Lidar : number unit \"m\" (0:10)\n");
        Cli cli = new Cli();
        assertEquals(cli.out() + cli.err, 1, cli.run("verify", model.toString(), "--world", WORLD.toString(), "--duration", "30m",
                "--runs", "2", "--out", out("n").toString()));
        assertTrue(cli.out(), row(cli.out(), "lidarClear", "adaptive").endsWith("never evaluated: no value for roqme.Lidar"));
        assertTrue(cli.out(), row(cli.out(), "docks", "adaptive").endsWith("holds"));
        assertTrue(cli.out(), row(cli.out(), "overfull", "adaptive").endsWith("holds, open at the end in 2"));
        // the report says the verdicts as the table does
        String report = Files.readString(out("n").resolve("report.html"));
        assertTrue(report, report.contains("<td class=\"not-evaluated\">never evaluated: no value for roqme.Lidar</td>"));
        assertTrue(report, report.contains("<td class=\"holds\">holds, open at the end in 2</td>"));
        JsonNode summary = Json.MAPPER.readTree(out("n").resolve("summary.json").toFile());
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(summary));
        JsonNode lidar = summary.path("requirements").path("lidarClear").path("adaptive");
        assertEquals("not-evaluated", lidar.path("verdict").asText());
        assertEquals(2, lidar.path("notEvaluated").asInt());
    }

    @Test
    public void theHospitalRequirementsAreCheckedInItsWorld() throws Exception {
        Path model = Cli.ROOT.resolve("examples/hospital-delivery/hospital.miron");
        Cli cli = new Cli();
        int status = cli.run("verify", model.toString(), "--world", Cli.ROOT.resolve("examples/hospital-delivery/world.json").toString(),
                "--duration", "1h", "--runs", "2", "--out", out("h").toString());
        assertTrue(cli.out() + cli.err, status == 0 || status == 1);
        JsonNode summary = Json.MAPPER.readTree(out("h").resolve("summary.json").toFile());
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(summary));
        assertEquals(3, summary.path("requirements").size());
    }

    /** A copy of the intralogistics example whose requirements are these. */
    private static Path withRequirements(String requirements) throws Exception {
        Path dir = Examples.copy("intralogistics");
        Path model = dir.resolve("intralogistics.miron");
        String text = Files.readString(model);
        int from = text.indexOf("/** The Charge subtree");
        Files.writeString(model, text.substring(0, from) + requirements);
        return model;
    }

    /** --coverage in miron verify: the table after the requirements', the summary's coverage against the schema, the gate. */
    @Test
    public void coverageOfTheVerifiedRunsAndItsGate() throws Exception {
        Path model = Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron");
        String[] args = { "verify", model.toString(), "--world", WORLD.toString(), "--duration", "30m", "--runs", "1", "--seed", "1",
            "--out", out("c").toString(), "--coverage" };
        Cli cli = new Cli();
        int status = cli.run(args);
        assertEquals("as without --coverage: slowNearPeople is violated", 1, status);
        assertTrue(cli.out(), cli.out().matches("(?s).*\ncoverage  item +adaptive\n.*\nrule      noBattery .*"));
        JsonNode summary = Json.MAPPER.readTree(out("c").resolve("summary.json").toFile());
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(summary));
        JsonNode adaptive = summary.path("coverage").path("adaptive");
        assertTrue(adaptive.toString(), adaptive.path("covered").asInt() > 0 && adaptive.path("nodes").size() > 5);
        ((com.fasterxml.jackson.databind.node.ObjectNode) adaptive).put("extra", 1);
        assertEquals("the schema is strict", 1, JsonSchemaFile.VERIFY_SUMMARY.problems(summary).size());
        assertTrue(Files.readString(out("c").resolve("report.html")).contains("<h2>Coverage</h2>"));
        args[args.length - 1] = "--min-coverage=100";
        Cli gated = new Cli();
        assertEquals(1, gated.run(args));
        assertTrue(gated.err.toString(), gated.err.toString().contains("miron verify: coverage of adaptive is "));
    }
}
