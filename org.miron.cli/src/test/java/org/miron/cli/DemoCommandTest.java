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
 * whole loop runs on loopback with the real minizinc, closed-loop on the example's demo world (the
 * skills act on it, it publishes the contexts), the console tells the adaptations in order and the
 * report shows them.
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
        // Every adaptation says why: the rule that forced it, the impacts, or the preset nothing overrode.
        assertTrue(told, told.contains("ADAPT   task -> dock (behaviour tree switches branch): rule noBattery (power_autonomy = 0."));
        assertTrue(told, told.contains("ADAPT   task -> pickDeliverCharge (behaviour tree switches branch): the preset: "
                + "no rule or impact asks for another value"));
        // The virtual clock against the real one: the simulator on the same world and seed takes the
        // same decisions in the same order (the live run may stop a little earlier or later), compared
        // per variation point. The live engine decides on each estimate as it arrives, so where the
        // model's choice of speed is marginal (+0.02 either way once the person has gone) it may
        // answer an in-between state the virtual clock, all of an instant's inputs at once, never
        // shows (on a loaded machine, a step between 100 and 10): the live run is checked for the
        // slow-down and the return to full speed, the task through the whole run.
        List<String> live = new ArrayList<>();
        for (String line : Files.readAllLines(temp.getRoot().toPath().resolve("decisions.jsonl"))) {
            live.addAll(changes(org.miron.runtime.Json.MAPPER.readTree(line)));
        }
        Path generated = temp.getRoot().toPath().resolve("model");
        var roqme = org.miron.runtime.roqme.model.ModelReader.read(generated.resolve("intralogistics.roqme.json"));
        Path tree = generated.resolve("intralogistics.ext.xml");
        var setup = new org.miron.runtime.sim.Setup(org.miron.runtime.engine.IoModel.load(generated.resolve("intralogistics.io.json")),
                roqme, tree, org.miron.runtime.sim.WorldReader.read(new File(ROOT, "examples/intralogistics/demo/world.json").toPath(),
                        org.miron.runtime.sim.Setup.env(tree, roqme)));
        List<String> virtual = new ArrayList<>();
        new org.miron.runtime.sim.Simulation(setup, org.miron.runtime.sim.Policy.parse("adaptive"), 1, 150_000, 150_000).run()
                .timeline().stream().filter(e -> e.topic().equals("miron.decision")).forEach(e -> virtual.addAll(changes(e.body())));
        String both = "live " + live + " vs virtual " + virtual;
        List<String> speeds = List.of("maxVelocity=100", "maxVelocity=10", "maxVelocity=100");
        assertEquals(both, speeds, only("maxVelocity", virtual).subList(0, 3));
        List<String> liveSpeeds = only("maxVelocity", live);
        int slowed = liveSpeeds.indexOf("maxVelocity=10");
        assertTrue(both, liveSpeeds.get(0).equals("maxVelocity=100") && slowed > 0
                && liveSpeeds.subList(slowed, liveSpeeds.size()).contains("maxVelocity=100"));
        for (List<String> run : List.of(live, virtual)) { // slowed down for the person before the battery ran low
            assertTrue(both, run.indexOf("maxVelocity=10") < run.indexOf("task=dock"));
        }
        List<String> liveTasks = only("task", live);
        List<String> virtualTasks = only("task", virtual);
        assertTrue(both, liveTasks.size() >= 3 && virtualTasks.size() >= liveTasks.size());
        assertEquals(both, virtualTasks.subList(0, liveTasks.size()), liveTasks);
    }

    private static List<String> only(String varpoint, List<String> changes) {
        return changes.stream().filter(c -> c.startsWith(varpoint + "=")).toList();
    }

    /** What a decision changed: varpoint=value, in the order the engine lists them. */
    private static List<String> changes(com.fasterxml.jackson.databind.JsonNode decision) {
        List<String> out = new ArrayList<>();
        decision.path("changed").forEach(vp -> out.add(vp.asText() + "=" + decision.path("decisions").path(vp.asText()).asText()));
        return out;
    }

    /**
     * The same demo with the tree woven for BehaviorTree.CPP 4 and run with its semantics, and the
     * engine deciding with the reference backend (MiniZinc) instead of the default native one.
     */
    @Test
    public void theDemoRunsTheSameOnTheVersion4TreeAndWithMiniZincAndServesGroot2() throws Exception {
        int port = org.miron.testkit.runtime.GrootClient.freePortPair();
        java.util.concurrent.CompletableFuture<String> tree = java.util.concurrent.CompletableFuture.supplyAsync(() -> {
            try (org.miron.testkit.runtime.GrootClient groot = new org.miron.testkit.runtime.GrootClient(port)) {
                List<byte[]> reply = groot.requestUntilAnswered('T', 60_000);
                return reply == null ? "no reply" : org.miron.testkit.runtime.GrootClient.text(reply.get(1));
            }
        });
        String told = runDemo(4, "--bt-format", "4", "--backend", "minizinc", "--groot", Integer.toString(port));
        assertTrue(told, told.contains("intralogistics.ext.xml runs as BehaviorTree.CPP 4; the engine decides "
                + "with the minizinc backend."));
        assertTrue(told, told.contains("MIRoN demo: Groot2 can connect to 127.0.0.1:" + port));
        String xml = tree.get(10, java.util.concurrent.TimeUnit.SECONDS);
        assertTrue(xml, xml.contains("<VariantAction name=\"VariantAction\" _uid=\"3\""));
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

        // 90 s of the world in 36 s: the whole story (person, low battery, dock, charge, back) with room for a loaded machine
        List<String> arguments = new ArrayList<>(List.of("demo", "--out", dir.toString(), "--time-scale", "0.4", "--duration", "90s"));
        arguments.addAll(List.of(options));
        int status = cli.execute(arguments.toArray(String[]::new));

        String told = out.toString();
        assertEquals(err.toString() + told, 0, status);
        assertTrue(told, told.contains("the skills act on examples/intralogistics/demo/world.json, which publishes the robot's "
                + "contexts (closed loop) for 90s of world time"));
        assertTrue(told, !told.contains("no demo/") && !told.contains("scenario"));
        // A person comes close: the provider's safety drops, the velocity parameter goes down, then back up.
        int safetyLow = told.indexOf("personNearby fired: undermines safety → safety");
        int slow = told.indexOf("ADAPT   maxVelocity -> 10 (change-parameter SmartCdServer transvel)");
        int fast = told.indexOf("ADAPT   maxVelocity -> 100", slow);
        assertTrue(told, 0 <= safetyLow && safetyLow < slow && slow < fast);
        // The battery runs low: the tree switches to the Charge subtree, then back after charging.
        int batteryLow = told.indexOf("batteryLow fired: undermines power_autonomy (veryhigh)");
        int dock = told.indexOf("ADAPT   task -> dock (behaviour tree switches branch)");
        int charged = told.indexOf("ADAPT   task -> pickDeliverCharge", dock);
        assertTrue(told, 0 <= batteryLow && batteryLow < dock && dock < charged);
        // Closed loop: the battery drained because the robot drove; it charges because the robot is at the dock.
        // The robot may already be on its way to the dock (the nominal mission ends there) when the battery
        // runs low, and may start for it before the console has told the decision: so what is checked is that
        // it drove to the dock, was docked when the charge came, and left only after the task went back.
        int docked = told.lastIndexOf("RoQME   Docked = true", charged);
        int undocked = told.lastIndexOf("RoQME   Docked = false", charged);
        int toDock = told.lastIndexOf("ROBOT   MoveTo x=-9.33 y=2.17", docked);
        int charging = told.indexOf("charging fired: reinforces power_autonomy", dock);
        int full = told.indexOf("batteryHigh fired: reinforces power_autonomy", dock);
        assertTrue(told, 0 < toDock && toDock < docked && undocked < docked
                && (0 < charging && charging < charged || 0 < full && full < charged));
        // ... and delivers: the drop's DeliveryDone event comes from the world
        assertTrue(told, told.indexOf("RoQME   DeliveryDone = true", told.indexOf("ROBOT   objectdrop")) > 0);
        java.util.regex.Matcher changes = java.util.regex.Pattern.compile("(\\d+) parameter changes applied by the skill interface").matcher(told);
        assertTrue(told, changes.find() && Integer.parseInt(changes.group(1)) >= 3);
        assertTrue(told, !told.contains("scripts"));

        String report = Files.readString(dir.resolve("report.html"));
        assertTrue(report.contains("<td>task</td><td>pickDeliverCharge</td><td>dock</td>"));
        // from full speed, or from a step the engine took on the way (see the live/virtual comparison)
        assertTrue(report.matches("(?s).*<td>maxVelocity</td><td>[0-9.]+</td><td>10</td>.*"));
        assertTrue(report.contains("<h2>Observations fired</h2>"));
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
    public void theExecutorIsJavaOrBtcppOnVersion4() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setErr(new PrintWriter(err, true));
        assertEquals(2, cli.execute("demo", "--executor", "python", "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("--executor must be java or btcpp, not python"));
        assertEquals(2, cli.execute("demo", "--executor", "btcpp", "--bt-format", "3", "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("--executor btcpp runs BehaviorTree.CPP 4 trees"));
    }

    @Test
    public void aWorldSaysHowLongItsSkillsTakeAndPublishesTheContexts() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setErr(new PrintWriter(err, true));
        String world = new File(ROOT, "examples/intralogistics/demo/world.json").getPath();
        assertEquals(2, cli.execute("demo", "--world", world, "--skills", new File(ROOT, "examples/intralogistics/demo/skills.json").getPath(),
                "--out", temp.getRoot().getPath()));
        assertEquals(2, cli.execute("demo", "--world", world, "--scenario", new File(ROOT, "examples/intralogistics/demo/scenario.json").getPath(),
                "--out", temp.getRoot().getPath()));
        assertTrue(err.toString(), err.toString().contains("--world excludes --scenario and --skills"));
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

    /**
     * The second example tells its own story from its own demo/ inputs: near misses and a dense
     * corridor undermine safety (careful navigation, slow and wide), they disturb the ward (the robot
     * disinfects after the handover), a low battery (a derived context the provider publishes)
     * sends it to charge first, and a charge brings it back.
     */
    @Test
    public void theHospitalDemoTellsItsOwnStory() throws Exception {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        Path dir = temp.getRoot().toPath();
        int status = cli.execute("demo", "--model", new File(ROOT, "examples/hospital-delivery/hospital.miron").getPath(),
                "--out", dir.toString(), "--time-scale", "0.4");
        String told = out.toString();
        assertEquals(err.toString() + told, 0, status);
        assertEquals("", err.toString());
        assertTrue(told, !told.contains("no demo/"));
        assertTrue(told, !told.contains("Intralogistics") && !told.contains("BatteryLevel"));
        int nearMiss = told.indexOf("nearMisses fired: undermines safety (high) → safety");
        int careful = told.indexOf("ADAPT   navigation -> careful", nearMiss);
        int wide = told.indexOf("ADAPT   inflation -> 0.8", nearMiss);
        assertTrue(told, 0 <= nearMiss && nearMiss < careful && nearMiss < wide);
        assertTrue(told, told.contains("crowded fired: undermines safety (veryhigh)"));
        assertTrue(told, told.contains("nearMisses fired: undermines comfort → comfort"));
        // the derived context lowBattery (battery < 25) comes from the provider and triggers the rule
        int low = told.indexOf("RoQME   lowBattery = true");
        int charge = told.indexOf("ADAPT   preparation -> charge (behaviour tree switches branch): rule lowBattery (lowBattery = true");
        int draining = told.indexOf("draining fired: undermines autonomy (high) → autonomy");
        int charged = told.indexOf("charged fired: clears autonomy, reinforces autonomy (high) → autonomy");
        int none = told.indexOf("ADAPT   preparation -> none", charge);
        assertTrue(told, 0 <= low && low < charge && charge < charged && charged < none && draining > low);
        assertTrue(told, told.indexOf("ROBOT   toCharger", charge) > 0);
        String report = Files.readString(dir.resolve("report.html"));
        assertTrue(report, report.contains("<tr><td>draining</td><td>undermines autonomy (HIGH)</td>"));
        // Each adaptation says why (issue 27's explanation), inputs in the model's names.
        assertTrue(report, report.contains("<td>0.8</td><td>rule crowdedCorridor (crowding = "));
        assertTrue(report, !report.contains("metric_Hospital_") && !report.contains("context_Hospital_"));
        assertTrue(report, report.matches("(?s).*<td>[^<]*qos\\.safety = [0-9.]+[^<]*</td>.*"));
        // The woven tree after the decision to charge first: the ChargeFirst branch of the
        // preparation Switch (Main's mission, second child) outlined, the default branch dimmed.
        int figure = report.indexOf("preparation → charge", report.indexOf("<h2>Behaviour tree</h2>"));
        assertTrue(report, figure > 0);
        String charging = report.substring(figure, report.indexOf("</figure>", figure));
        assertTrue(charging, charging.matches("(?s).*<g class=\"[^\"]*\\bactive\\b[^\"]*\" data-id=\"0\\.1\\.1\\.0\".*"));
        assertTrue(charging, charging.matches("(?s).*<g class=\"[^\"]*\\binactive\\b[^\"]*\" data-id=\"0\\.1\\.1\\.2\".*"));
        // What the robot did: the charger run among the skills.
        String skills = report.substring(report.indexOf("<h2>Skills</h2>"));
        assertTrue(skills, skills.contains("toCharger") && skills.contains("class=\"skill-run\""));
    }

    /**
     * Issue 30: given only --model, a model without demo/ inputs gets the intralogistics scenario,
     * said at start; its inputs are not the hospital's, so the run is refused (exit 2) and each
     * unknown input named, unless --allow-unknown-inputs.
     */
    @Test
    public void aScenarioForAnotherModelIsRefused() throws Exception {
        Path model = temp.newFolder("hospital").toPath();
        for (String file : List.of("hospital.miron", "hospital.roqme", "hospital.bt")) {
            Files.copy(new File(ROOT, "examples/hospital-delivery/" + file).toPath(), model.resolve(file));
        }
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        Path dir = temp.newFolder("out").toPath();
        assertEquals(2, cli.execute("demo", "--model", model.resolve("hospital.miron").toString(), "--out", dir.toString()));
        assertTrue(out.toString(), out.toString().contains("no demo/scenario.json next to hospital.miron: using "));
        String refused = err.toString();
        assertTrue(refused, refused.contains("scenario.json: BatteryLevel (Intralogistics) is not an input of hospital.miron"));
        assertTrue(refused, refused.contains("scenario.json: HumanDistance (Intralogistics) is not an input of hospital.miron"));
        assertTrue(refused, refused.contains("--allow-unknown-inputs"));
        assertTrue(out.toString(), !out.toString().contains("ADAPT"));

        // a scripted estimate of a metric the model does not have is named too
        Path scenario = dir.resolve("scenario.json");
        Files.writeString(scenario, "[{\"at\": 0, \"estimate\": {\"name\": \"power_autonomy\", \"namespace\": \"Intralogistics\", \"value\": 0.9}},\n"
                + " {\"at\": 0, \"context\": {\"name\": \"battery\", \"namespace\": \"Hospital\", \"type\": \"number\", \"value\": 80}}]");
        StringWriter err2 = new StringWriter();
        CommandLine again = MironCli.commandLine();
        again.setOut(new PrintWriter(new StringWriter(), true));
        again.setErr(new PrintWriter(err2, true));
        assertEquals(2, again.execute("demo", "--model", model.resolve("hospital.miron").toString(), "--scenario",
                scenario.toString(), "--out", dir.toString()));
        assertTrue(err2.toString(), err2.toString().startsWith(
                "scenario.json: power_autonomy (Intralogistics) is not an input of hospital.miron"));
        assertTrue(err2.toString(), !err2.toString().contains("battery"));

        // asked to go on, it plays
        StringWriter out3 = new StringWriter();
        StringWriter err3 = new StringWriter();
        CommandLine anyway = MironCli.commandLine();
        anyway.setOut(new PrintWriter(out3, true));
        anyway.setErr(new PrintWriter(err3, true));
        assertEquals(err3.toString(), 0, anyway.execute("demo", "--model", model.resolve("hospital.miron").toString(), "--scenario",
                scenario.toString(), "--skills", new File(ROOT, "examples/hospital-delivery/demo/skills.json").getPath(),
                "--out", dir.toString(), "--time-scale", "0.2", "--allow-unknown-inputs"));
        assertTrue(err3.toString(), err3.toString().contains("playing it anyway"));
        assertTrue(out3.toString(), out3.toString().contains("RoQME   battery = 80"));
    }
}
