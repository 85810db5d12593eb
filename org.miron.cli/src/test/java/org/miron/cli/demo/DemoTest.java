package org.miron.cli.demo;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

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
import org.miron.runtime.player.Scenario;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.TestModels;

/**
 * The one-JVM demo end to end on loopback with the real minizinc: the battery runs low and the
 * robot docks, safety drops and the velocity parameter follows, both recover; the console tells
 * it and the report shows it.
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
        assertTrue(told, told.contains("RoQME   power_autonomy = 0.2"));
        assertTrue(told, told.contains("ADAPT   task -> dock (behaviour tree switches branch)"));
        assertTrue(told, told.contains("ADAPT   task -> pickDeliverCharge"));
        assertTrue(told, told.contains("ADAPT   maxVelocity -> 37 (change-parameter SmartCdServer transvel)"));
        assertTrue(told, told.contains("ROBOT   navigate x=-9.33 y=2.17"));
        // The dock decision comes after the low battery reading, the velocity one after low safety.
        assertTrue(told, told.indexOf("power_autonomy = 0.2") < told.indexOf("task -> dock"));
        assertTrue(told, told.indexOf("safety = 0.3") < told.indexOf("maxVelocity -> 37"));

        assertTrue(result.adaptations() >= 4);
        assertTrue("transvel changes reached the skill interface", result.parameterChanges() >= 2);
        List<String> log = Files.readAllLines(result.decisionLog());
        assertTrue(log.size() >= 4);

        String report = Files.readString(result.report());
        assertTrue(report.startsWith("<!DOCTYPE html>"));
        assertTrue(report, report.contains("<svg"));
        assertTrue(report, report.contains("<td>task</td><td>pickDeliverCharge</td><td>dock</td>"));
        assertTrue(report, report.contains("metric_Intralogistics_power_autonomy = 0.2"));
        assertEquals("the report names every metric", 2,
                List.of("power_autonomy", "safety").stream().filter(report::contains).count());
    }
}
