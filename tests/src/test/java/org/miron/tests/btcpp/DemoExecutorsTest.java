package org.miron.tests.btcpp;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.demo.Demo;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.RepositoryRoot;

/**
 * The intralogistics demo (v4 weaving) with the robot on the Java executor and on the real
 * BehaviorTree.CPP 4 (miron-btcpp-run): the same adaptations of the behaviour tree in the same
 * order, and the same skills: the same set of distinct skill pushes, the same first one, and after
 * each switch of the task the other branch's first skill. What is left out depends on the
 * machine's timing, not on the executor: how many skills fit between two adaptations, and whether
 * the person nearby (a burst of contexts the loaded machine may deliver late) lowers safety enough
 * to slow the robot down (maxVelocity is a change-parameter the engine sends the skill interface
 * itself; the executor never sees it).
 */
public class DemoExecutorsTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();
    private static Path generated;

    @BeforeClass
    public static void weave() throws Exception {
        BtcppRunner.assumeBuilt();
        generated = temp.newFolder("model").toPath();
        BtcppRunner.weaveV4(generated, "intralogistics/intralogistics.miron");
    }

    /** One demo run. (A class, not a record: Gradle 4.4's test scanner does not read records.) */
    private static final class Run {
        private final String told;
        private final List<String> adaptations;
        private final List<String> pushes;
        private final Path recording;

        Run(String told, List<String> adaptations, List<String> pushes, Path recording) {
            this.told = told;
            this.adaptations = adaptations;
            this.pushes = pushes;
            this.recording = recording;
        }

        String told() {
            return told;
        }

        List<String> adaptations() {
            return adaptations;
        }

        List<String> pushes() {
            return pushes;
        }
    }

    private static Run run(Path runner) throws Exception {
        Path example = RepositoryRoot.path().resolve("examples/intralogistics");
        CompiledModel roqme = Compiler.compile(ModelReader.read(generated.resolve("intralogistics.roqme.json")),
                new java.util.LinkedHashMap<>());
        StringWriter console = new StringWriter();
        Path recording = temp.newFolder().toPath().resolve("run.btlog");
        Demo.Result result = new Demo(generated.resolve("intralogistics.io.json"), generated.resolve("intralogistics.ext.xml"),
                Scenario.load(example.resolve("demo/scenario.json")), SkillTable.load(example.resolve("demo/skills.json")),
                temp.newFolder().toPath(), Endpoints.freeLoopback(), new PrintWriter(console, true))
                .timeScale(0.5).provider(roqme, 1000).btcpp(runner).record(recording).run();
        List<String> adaptations = new ArrayList<>();
        for (String line : Files.readAllLines(result.decisionLog())) {
            JsonNode decision = Json.MAPPER.readTree(line);
            decision.path("changed").forEach(vp -> {
                if (vp.asText().equals("task")) { // the varpoint bound to the tree
                    adaptations.add("task -> " + decision.path("decisions").path("task").asText());
                }
            });
        }
        List<String> pushes = new ArrayList<>();
        // in-attributes by name: the two executors write them in different orders
        result.skillsPushed().forEach(s -> pushes.add(s.path("name").asText() + " "
                + Json.MAPPER.convertValue(s.path("in-attribute"), java.util.TreeMap.class)));
        return new Run(console.toString(), adaptations, pushes, recording);
    }

    @Test
    public void bothExecutorsAdaptAndActAlike() throws Exception {
        Run java = run(null);
        Run cpp = run(BtcppRunner.EXECUTABLE);
        assertTrue(cpp.told(), cpp.told().contains("runs on the real BehaviorTree.CPP 4"));
        assertEquals("adaptations\njava:\n" + java.told() + "\nbtcpp:\n" + cpp.told(), java.adaptations(), cpp.adaptations());
        assertTrue(java.adaptations().toString(), java.adaptations().contains("task -> dock"));
        assertEquals("the first skill", java.pushes().get(0), cpp.pushes().get(0));
        assertEquals("the distinct skills", new LinkedHashSet<>(java.pushes()).stream().sorted().toList(),
                new LinkedHashSet<>(cpp.pushes()).stream().sorted().toList());
        // --record on either executor: the same recorded tree, and the bus log holds the run's adaptations
        org.miron.runtime.recording.Recording javaLog = org.miron.runtime.recording.BtlogReader.read(java.recording);
        org.miron.runtime.recording.Recording cppLog = org.miron.runtime.recording.BtlogReader.read(cpp.recording);
        assertEquals(org.miron.runtime.recording.RecordedTree.parse(javaLog.treeXml()).nodes(),
                org.miron.runtime.recording.RecordedTree.parse(cppLog.treeXml()).nodes());
        for (Run run : List.of(java, cpp)) {
            List<String> logged = new ArrayList<>();
            for (org.miron.runtime.recording.BusLogReader.BusEvent e : org.miron.runtime.recording.BusLogReader.read(
                    org.miron.runtime.recording.Btlog.busLogOf(run.recording))) {
                if (e.topic().equals("miron.decision")) {
                    e.message().path("changed").forEach(vp -> {
                        if (vp.asText().equals("task")) {
                            logged.add("task -> " + e.message().path("decisions").path("task").asText());
                        }
                    });
                }
            }
            assertEquals("the bus log's adaptations", run.adaptations(), logged);
        }
        assertTrue(cppLog.transitions().size() > 20 && javaLog.transitions().size() > 20);
        for (Run run : List.of(java, cpp)) {
            int dock = run.told().indexOf("ADAPT   task -> dock");
            int resume = run.told().indexOf("ADAPT   task -> pickDeliverCharge", dock);
            assertTrue(run.told(), dock > 0 && resume > dock);
            assertTrue("the Charge branch's MoveTo after the dock decision\n" + run.told(),
                    nextSkill(run.told(), dock).equals("MoveTo x=-9.33 y=2.17"));
            assertTrue("the pick place after resuming\n" + run.told(),
                    nextSkill(run.told(), resume).equals("MoveTo x=-2.5 y=6.4")
                            || nextSkill(run.told(), resume).equals("MoveTo x=-2.50 y=6.40"));
        }
    }

    /** The first skill the robot started after position {@code from} of the console. */
    private static String nextSkill(String told, int from) {
        for (String line : told.substring(from).split("\n")) {
            int robot = line.indexOf("ROBOT   ");
            if (robot >= 0 && !line.contains("mission ")) {
                return line.substring(robot + "ROBOT   ".length()).trim();
            }
        }
        return "";
    }
}
