package org.miron.cli.demo;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.bt.BTModel;
import org.miron.bt.formats.BtFormatConverter;
import org.miron.bt.formats.Conversion;
import org.miron.bt.formatting2.BtFormatting;
import org.miron.executor.BtLoader;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.requirement.Verdict;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.TestModels;

/**
 * The one-JVM demo end to end on loopback with the real minizinc: the battery runs low and the
 * robot docks, safety drops and the velocity parameter follows, both recover; the console tells
 * it and the report shows it. On the intralogistics example the metrics are the RoQME provider's,
 * computed from the example's observations; without a provider, a scenario's scripted estimates
 * still drive the loop.
 */
public class DemoTest {
    private static final Path ROOT = RepositoryRoot.path();
    /** The woven intralogistics tree of the executor's tests. */
    private static final Path WOVEN = ROOT.resolve("org.miron.executor/src/test/resources/executor/intralogistics.ext.xml");

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void batteryAndSafetyDrivesAdaptationsThatAreToldAndReported() throws Exception {
        runAndCheck(WOVEN, 3);
    }

    /** The woven tree converted to BehaviorTree.CPP 4 (as `miron convert --to 4`) adapts the same way. */
    @Test
    public void itsVersion4ConversionAdaptsTheSameWay() throws Exception {
        BTModel model = new BtLoader().load(WOVEN).model();
        Conversion conversion = BtFormatConverter.convert(model, 4);
        assertTrue(conversion.getProblems().toString(), conversion.succeeded());
        String v4 = BtFormatting.print(model);
        assertTrue(v4, v4.contains("BTCPP_format=\"4\"") && v4.contains("<SubTree ") && !v4.contains("SubTreePlus"));
        Path tree = temp.newFolder("v4").toPath().resolve("intralogistics.ext.xml");
        Files.writeString(tree, v4);
        runAndCheck(tree, 4);
    }

    private void runAndCheck(Path tree, int version) throws Exception {
        SkillTable.Entry move = new SkillTable.Entry(300, "SUCCESS", NullNode.getInstance(), Json.object());
        SkillTable.Entry hand = new SkillTable.Entry(100, "SUCCESS", NullNode.getInstance(), Json.object());
        StringWriter console = new StringWriter();
        Demo demo = new Demo(TestModels.copy("testbot", temp.newFolder("model" + version).toPath()),
                tree,
                Scenario.load(Path.of("src/test/resources/demo/short.scenario.json")),
                new SkillTable(Map.of("navigate", move, "objectpick", hand, "objectdrop", hand)),
                temp.getRoot().toPath(), Endpoints.freeLoopback(), new PrintWriter(console, true));

        Demo.Result result = demo.run();

        String told = console.toString();
        assertTrue(told, told.contains(tree.getFileName() + " runs as BehaviorTree.CPP " + version + ";"));
        assertTrue(told, told.contains("RoQME   power_autonomy 0.90 → 0.20"));
        assertTrue(told, told.contains("ADAPT   task -> dock (behaviour tree switches branch)"));
        assertTrue(told, told.contains("ADAPT   task -> pickDeliverCharge"));
        assertTrue(told, told.contains("ADAPT   maxVelocity -> 37 (change-parameter SmartCdServer transvel)"));
        assertTrue(told, told.contains("ROBOT   navigate x=-9.33 y=2.17"));
        // The dock decision comes after the low battery reading, the velocity one after low safety.
        assertTrue(told, told.indexOf("power_autonomy 0.90 → 0.20") < told.indexOf("task -> dock"));
        assertTrue(told, told.indexOf("safety 0.90 → 0.30") < told.indexOf("maxVelocity -> 37"));

        assertTrue(result.adaptations() >= 4);
        assertTrue("transvel changes reached the skill interface", result.parameterChanges() >= 2);
        List<String> log = Files.readAllLines(result.decisionLog());
        assertTrue(log.size() >= 4);

        String report = Files.readString(result.report());
        assertTrue(report.startsWith("<!DOCTYPE html>"));
        assertTrue(report, report.contains("<svg"));
        assertTrue(report, report.contains("<td>task</td><td>pickDeliverCharge</td><td>dock</td>"));
        // The inputs in the model's names, not the MiniZinc parameters'.
        assertTrue(report, report.contains("power_autonomy = 0.2"));
        assertFalse(report, report.contains("metric_Intralogistics_"));
        assertEquals("the report names every metric", 2,
                List.of("power_autonomy", "safety").stream().filter(report::contains).count());
    }

    /**
     * Requirements checked live beside the engine (a hand-written testbot.requirements.json, as
     * `miron generate` will write it): at time scale 0.5 the violation is told at the instant the
     * low safety arrived, on the console's axis, then met again; a requirement over a context that
     * never comes is never evaluated; the verdicts close the run and the report lists the violation.
     */
    @Test
    public void requirementsAreCheckedLiveToldAsTheyHappenAndReported() throws Exception {
        SkillTable.Entry move = new SkillTable.Entry(300, "SUCCESS", NullNode.getInstance(), Json.object());
        StringWriter console = new StringWriter();
        Path out = temp.newFolder("req").toPath();
        Demo.Result result = new Demo(TestModels.copy("testbot", temp.newFolder("reqmodel").toPath()), WOVEN,
                Scenario.load(Path.of("src/test/resources/demo/short.scenario.json")),
                new SkillTable(Map.of("*", move)), out, Endpoints.freeLoopback(), new PrintWriter(console, true))
                .timeScale(0.5).requirements(RequirementModel.load(Path.of("src/test/resources/demo/testbot.requirements.json")))
                .run();

        String told = console.toString();
        java.util.regex.Matcher low = java.util.regex.Pattern.compile("(\\d+\\.\\d) s  RoQME   safety 0\\.90 → 0\\.30").matcher(told);
        java.util.regex.Matcher violated = java.util.regex.Pattern
                .compile("(\\d+\\.\\d) s  REQ     alwaysSafe violated: roqme\\.safety = 0\\.3\\n").matcher(told);
        assertTrue(told, low.find() && violated.find());
        assertEquals(told, Double.parseDouble(low.group(1)), Double.parseDouble(violated.group(1)), 0.15);
        assertTrue(told, told.contains("REQ     alwaysSafe met again"));
        assertTrue(told, told.indexOf("alwaysSafe violated") < told.indexOf("alwaysSafe met again"));
        assertTrue(told, told.contains("REQ     alwaysSafe: violated once over the run, first at " + violated.group(1) + " s"));
        assertTrue(told, told.contains("REQ     ghostLow: never evaluated: no value for roqme.Ghost"));
        assertTrue(told, told.contains("REQ     slowWhenUnsafe: "));
        assertEquals(List.of("alwaysSafe", "slowWhenUnsafe", "ghostLow"),
                result.requirements().stream().map(r -> r.name()).toList());
        assertEquals(Verdict.VIOLATED, result.requirements().get(0).verdict());
        assertEquals(Verdict.NOT_EVALUATED, result.requirements().get(2).verdict());

        String report = Files.readString(result.report());
        assertTrue(report, report.contains("<h2>Requirements</h2>"));
        assertTrue(report, report.contains("<tr class=\"violation\"><td>alwaysSafe</td><td>" + violated.group(1) + "</td>"));
        assertTrue(report, report.contains("<td>ghostLow</td><td>not-evaluated</td><td>0</td>"));
    }

    @Test
    public void theDemoChecksTheGeneratedRequirementsOnlyWhenThereAreSome() throws Exception {
        Path generated = temp.newFolder("generated").toPath();
        assertNull("no file: nothing to check", DemoRequirements.load(generated, "testbot"));
        Files.writeString(generated.resolve("testbot.requirements.json"),
                "{\"format\":1,\"model\":\"testbot\",\"signals\":[],\"requirements\":[]}");
        assertNull("no requirement: nothing to check", DemoRequirements.load(generated, "testbot"));
        Files.copy(Path.of("src/test/resources/demo/testbot.requirements.json"), generated.resolve("testbot.requirements.json"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        assertEquals(3, DemoRequirements.load(generated, "testbot").requirements().size());
    }

    /**
     * The intralogistics example as `miron demo` runs it: its scenario publishes contexts only, the
     * provider computes the metrics from intralogistics.roqme, and the adaptations follow the
     * observations that fired: a person nearby (safety) slows the robot down, a low battery
     * (power_autonomy) sends it to the Charge subtree, a recharge brings it back.
     */
    @Test
    public void theExampleAdaptsOnTheMetricsTheProviderComputes() throws Exception {
        Path example = ROOT.resolve("examples/intralogistics");
        Path generated = temp.newFolder("model").toPath();
        assertEquals(0, org.miron.cli.MironCli.commandLine().execute("generate", "-o", generated.toString(),
                example.resolve("intralogistics.miron").toString()));
        Scenario scenario = Scenario.load(example.resolve("demo/scenario.json"));
        assertTrue("contexts only", scenario.steps().stream().allMatch(s -> s.topic().equals(Topics.CONTEXT)));
        CompiledModel roqme = Compiler.compile(ModelReader.read(generated.resolve("intralogistics.roqme.json")), new java.util.LinkedHashMap<>());
        StringWriter console = new StringWriter();
        Path out = temp.newFolder("out").toPath();
        Demo.Result result = new Demo(generated.resolve("intralogistics.io.json"), generated.resolve("intralogistics.ext.xml"),
                scenario, SkillTable.load(example.resolve("demo/skills.json")), out, Endpoints.freeLoopback(),
                new PrintWriter(console, true)).timeScale(0.3).provider(roqme, 1000).run();

        String told = console.toString();
        assertTrue(told, told.contains("the RoQME provider computes safety, mission_completion, power_autonomy"));
        // a person nearby: the provider undermines safety, the engine slows the robot down, then speeds up again
        int near = told.indexOf("personNearby fired: undermines safety → safety ");
        int slow = told.indexOf("ADAPT   maxVelocity -> 10 (change-parameter SmartCdServer transvel)");
        int fast = told.indexOf("ADAPT   maxVelocity -> 100", slow);
        assertTrue(told, 0 <= near && near < slow && slow < fast);
        // the battery runs low: batteryLow fires, the tree docks; the recharge clears that evidence and it resumes
        int low = told.indexOf("batteryLow fired: undermines power_autonomy (veryhigh)");
        int dock = told.indexOf("ADAPT   task -> dock (behaviour tree switches branch)");
        int recharged = told.indexOf("recharged fired: clears power_autonomy, reinforces power_autonomy (high)");
        int resume = told.indexOf("ADAPT   task -> pickDeliverCharge", dock);
        assertTrue(told, 0 <= low && low < dock && dock < recharged && recharged < resume);
        assertTrue(told, told.indexOf("ROBOT   MoveTo x=-9.33 y=2.17", dock) > 0); // the Charge subtree's dock
        assertTrue("transvel changes reached the skill interface", result.parameterChanges() >= 2);

        // the engine decided on the provider's numbers: safety below mission_completion, power_autonomy below 0.3
        List<JsonNode> decisions = new java.util.ArrayList<>();
        for (String line : Files.readAllLines(result.decisionLog())) {
            decisions.add(Json.MAPPER.readTree(line));
        }
        JsonNode slowDecision = decisions.stream().filter(d -> d.path("decisions").path("maxVelocity").asDouble() == 10)
                .findFirst().orElseThrow();
        double safety = slowDecision.path("inputs").path("metric_Intralogistics_safety").asDouble();
        assertTrue(slowDecision.toString(), safety > 0 && safety < 0.5);
        JsonNode dockDecision = decisions.stream().filter(d -> d.path("decisions").path("task").asText().equals("dock"))
                .findFirst().orElseThrow();
        double autonomy = dockDecision.path("inputs").path("metric_Intralogistics_power_autonomy").asDouble();
        assertTrue(dockDecision.toString(), autonomy > 0 && autonomy < 0.3);

        String report = Files.readString(result.report());
        assertTrue(report, report.contains("<h2>Observations fired</h2>"));
        assertTrue(report, report.contains("<tr><td>batteryLow</td><td>undermines power_autonomy (VERYHIGH)</td>"));
        assertTrue(report, report.contains("<tr><td>personNearby</td><td>undermines safety (MEDIUM)</td>"));
        // one estimate curve per property, in the QoS metrics chart
        String chart = report.substring(report.indexOf("<h2>QoS metrics</h2>"), report.indexOf("<h2>Observations fired</h2>"));
        assertEquals(chart, 3, chart.split("<path ").length - 1);
        for (String property : List.of("safety", "mission_completion", "power_autonomy")) {
            assertTrue(chart, chart.contains(">" + property + "</text>"));
        }
    }

    /** No example relies on scripted estimates: every metric of every example is computed by the provider. */
    @Test
    public void noExampleScriptsAnEstimate() throws Exception {
        List<Path> scripted;
        try (java.util.stream.Stream<Path> files = Files.walk(ROOT.resolve("examples"))) {
            scripted = files.filter(Files::isRegularFile).filter(f -> {
                try {
                    return Files.readString(f).contains("\"estimate\"");
                } catch (java.io.IOException | java.io.UncheckedIOException e) {
                    return false; // not text
                }
            }).toList();
        }
        assertEquals(List.of(), scripted);
        assertTrue(Files.isRegularFile(ROOT.resolve("examples/intralogistics/demo/scenario.json")));
    }
}
