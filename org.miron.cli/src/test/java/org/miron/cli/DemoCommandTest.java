package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.BeforeClass;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.RepositoryRoot;

import picocli.CommandLine;

/**
 * `miron demo` end to end, as a newcomer runs it: the intralogistics example is generated, the
 * whole loop runs on loopback with the real minizinc, the console tells the adaptations in order
 * and the report shows them.
 */
public class DemoCommandTest {
    private static final File ROOT = RepositoryRoot.path().toFile();

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    /** As the ./miron launcher does: default model paths resolve against the checkout. */
    @BeforeClass
    public static void home() {
        System.setProperty("miron.home", ROOT.getAbsolutePath());
    }

    @Test
    public void theRobotDocksWhenTheBatteryRunsLowAndSlowsDownWhenSafetyDrops() throws Exception {
        String told = runDemo(3);
        assertTrue(told, told.contains("intralogistics.ext.xml runs as BehaviorTree.CPP 3; the engine decides "
                + "with the native backend."));
    }

    /**
     * The same demo with the tree woven for BehaviorTree.CPP 4 and run with its semantics, and the
     * engine deciding with the reference backend (MiniZinc) instead of the default native one.
     */
    @Test
    public void theDemoRunsTheSameOnTheVersion4TreeAndWithMiniZinc() throws Exception {
        String told = runDemo(4, "--bt-format", "4", "--backend", "minizinc");
        assertTrue(told, told.contains("intralogistics.ext.xml runs as BehaviorTree.CPP 4; the engine decides "
                + "with the minizinc backend."));
    }

    @Test
    public void anUnknownBackendIsAUsageErrorNamingTheBackends() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(new StringWriter(), true));
        cli.setErr(new PrintWriter(err, true));
        assertEquals(2, cli.execute("demo", "--backend", "gurobi", "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("gurobi") && err.toString().contains("native")
                && err.toString().contains("minizinc"));
    }

    private String runDemo(int version, String... options) throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        Path dir = temp.getRoot().toPath();

        List<String> arguments = new ArrayList<>(List.of("demo", "--out", dir.toString(), "--time-scale", "0.4"));
        arguments.addAll(List.of(options));
        int status = cli.execute(arguments.toArray(String[]::new));

        String told = out.toString();
        assertEquals(err.toString() + told, 0, status);
        // Safety drops when a person comes close: the velocity parameter goes down, then back up.
        int safetyLow = told.indexOf("RoQME   safety = 0.35");
        int slow = told.indexOf("ADAPT   maxVelocity -> 10 (change-parameter SmartCdServer transvel)");
        int fast = told.indexOf("ADAPT   maxVelocity -> 100", slow);
        assertTrue(told, 0 <= safetyLow && safetyLow < slow && slow < fast);
        // The battery runs low: the tree switches to the Charge subtree, then back after charging.
        int batteryLow = told.indexOf("RoQME   power_autonomy = 0.25");
        int dock = told.indexOf("ADAPT   task -> dock (behaviour tree switches branch)");
        int charged = told.indexOf("ADAPT   task -> pickDeliverCharge", dock);
        assertTrue(told, 0 <= batteryLow && batteryLow < dock && dock < charged);
        assertTrue(told, told.indexOf("ROBOT   MoveTo x=-9.33 y=2.17", batteryLow) > 0);
        assertTrue(told, told.contains("3 parameter changes applied by the skill interface"));

        String report = Files.readString(dir.resolve("report.html"));
        assertTrue(report.contains("<td>task</td><td>pickDeliverCharge</td><td>dock</td>"));
        assertTrue(report.contains("<td>maxVelocity</td><td>100</td><td>10</td>"));
        assertTrue(Files.readAllLines(dir.resolve("decisions.jsonl")).size() >= 4);
        String tree = Files.readString(dir.resolve("model/intralogistics.ext.xml"));
        assertEquals(tree, version == 4, tree.contains("BTCPP_format=\"4\""));
        return told;
    }

    @Test
    public void onlyBehaviorTreeCpp3And4AreFormats() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setErr(new PrintWriter(err, true));
        assertEquals(2, cli.execute("demo", "--bt-format", "5", "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("--bt-format must be 3 or 4, not 5"));
    }

    @Test
    public void aMissingScenarioIsAUsageError() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setErr(new PrintWriter(err, true));
        assertEquals(2, cli.execute("demo", "--scenario", new File(temp.getRoot(), "none.json").getPath(),
                "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("none.json: error: no such file"));
    }
}
