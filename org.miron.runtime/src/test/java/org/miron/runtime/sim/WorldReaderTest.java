package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;
import org.miron.runtime.roqme.model.RoqmeModel;

/** Bad world files are refused before anything runs, each problem at its line and column. */
public class WorldReaderTest {
    private static final WorldEnv ENV = new WorldEnv(
            Map.of("MoveTo", Set.of("x", "y"), "objectdrop", Set.of("obj_index")),
            Map.of("BatteryLevel", new RoqmeModel.Type("number", null, 0.0, 100.0, null, "%"),
                    "Docked", new RoqmeModel.Type("boolean", null, null, null, null, null),
                    "FreeSpace", new RoqmeModel.Type("enum", List.of("LOW", "MEDIUM", "HIGH"), null, null, null, null),
                    "DeliveryDone", new RoqmeModel.Type("eventtype", null, null, null, null, null)));

    /** A valid world; each test breaks one line of it. */
    private static final String GOOD = String.join("\n",
            "{",
            "  \"places\": { \"dock\": { \"x\": 0, \"y\": 0 }, \"shelf\": { \"x\": 30, \"y\": 40 } },",
            "  \"start\": \"dock\",",
            "  \"state\": {",
            "    \"battery\": { \"type\": \"number\", \"initial\": 80, \"min\": 0, \"max\": 100 },",
            "    \"docked\": { \"type\": \"boolean\", \"initial\": true },",
            "    \"space\": { \"type\": \"enum\", \"values\": [\"LOW\", \"HIGH\"], \"initial\": \"HIGH\" }",
            "  },",
            "  \"parameters\": { \"transvel\": 100 },",
            "  \"events\": [\"DeliveryDone\"],",
            "  \"skills\": {",
            "    \"MoveTo\": { \"target\": { \"x\": \"x\", \"y\": \"y\" }, \"duration\": \"distance / (transvel / 100)\",",
            "                \"perSecond\": { \"battery\": \"-0.1\" }, \"end\": \"docked = place == 'dock'\" },",
            "    \"objectdrop\": { \"duration\": \"5\", \"events\": [\"DeliveryDone\"] }",
            "  },",
            "  \"contexts\": {",
            "    \"BatteryLevel\": { \"value\": \"battery\", \"every\": \"1s\" },",
            "    \"FreeSpace\": { \"value\": \"space\" },",
            "    \"DeliveryDone\": { \"event\": \"DeliveryDone\" }",
            "  },",
            "  \"measures\": {",
            "    \"deliveries\": { \"count\": \"DeliveryDone\" },",
            "    \"low\": { \"fraction\": \"battery < 20\" }",
            "  }",
            "}");

    @Test
    public void theGoodWorldIsRead() throws Exception {
        WorldModel w = WorldReader.read(GOOD, "w.json", ENV);
        assertEquals(Set.of("MoveTo", "objectdrop"), w.skills().keySet());
        assertEquals(2, w.measures().size());
        assertEquals(3, w.publications().size());
    }

    @Test
    public void unknownSkill() {
        assertProblem(GOOD.replace("\"objectdrop\": { \"duration\"", "\"objectdorp\": { \"duration\""),
                "w.json:14:5: error [world.unknown-skill]: unknown skill 'objectdorp'");
    }

    @Test
    public void unknownContext() {
        assertProblem(GOOD.replace("\"FreeSpace\": { \"value\"", "\"FreeSpaces\": { \"value\""),
                "w.json:18:5: error [world.unknown-context]: unknown context 'FreeSpaces'");
    }

    @Test
    public void unknownPlace() {
        assertProblem(GOOD.replace("\"start\": \"dock\"", "\"start\": \"dok\""),
                "w.json:3:12: error [world.unknown-place]: unknown place 'dok'");
    }

    @Test
    public void typeErrorInAnExpressionIsPlacedAtItsCharacter() {
        // line 13: "perSecond": { "battery": "-0.1" } becomes a boolean rate; then a comparison of a
        // number with a text, placed at the comparison inside the string.
        assertProblem(GOOD.replace("\"-0.1\"", "\"docked\""), "w.json:13:43: error [world.type]: 'docked' is a boolean, a number is needed here");
        assertProblem(GOOD.replace("\"low\": { \"fraction\": \"battery < 20\" }", "\"low\": { \"fraction\": \"battery == 'full'\" }"),
                "w.json:23:27: error [world.type]: cannot compare a number with 'full'");
    }

    @Test
    public void enumValueTypos() {
        assertProblem(GOOD.replace("\"low\": { \"fraction\": \"battery < 20\" }", "\"low\": { \"fraction\": \"space == 'HIHG'\" }"),
                "w.json:23:27: error [world.type]: enum space is never 'HIHG'");
    }

    @Test
    public void unknownNameInAnEffect() {
        assertProblem(GOOD.replace("docked = place == 'dock'", "dockd = place == 'dock'"),
                "w.json:13:61: error [world.unknown-name]: unknown state variable 'dockd'");
    }

    @Test
    public void measureOverNothing() {
        assertProblem(GOOD.replace("\"battery < 20\"", "\"1 < 20\""),
                "w.json:23:26: error [world.measure-over-nothing]: '1 < 20' reads no state");
        assertProblem(GOOD.replace("\"objectdrop\": { \"duration\": \"5\", \"events\": [\"DeliveryDone\"] }",
                "\"objectdrop\": { \"duration\": \"5\" }"), "error [world.measure-over-nothing]: no skill, outcome or process emits event 'DeliveryDone'");
    }

    @Test
    public void aContextOfTheWrongTypeAndASyntaxError() {
        assertProblem(GOOD.replace("\"value\": \"battery\", \"every\"", "\"value\": \"docked\", \"every\""),
                "w.json:17:32: error [world.type]: 'docked' is a boolean, a number is needed here");
        assertProblem(GOOD.replace("\"5\"", "\"5 +\""), "w.json:14:36: error [world.syntax]: the script ends too early");
        assertProblem(GOOD.replace("\"start\": \"dock\",", "\"start\": \"dock\""), "w.json:4:3: error [world.syntax]");
    }

    @Test
    public void aTreeSkillTheWorldDoesNotModel() {
        assertProblem(GOOD.replace(",\n    \"objectdrop\": { \"duration\": \"5\", \"events\": [\"DeliveryDone\"] }", "")
                .replace("\"deliveries\": { \"count\": \"DeliveryDone\" },", ""),
                "error [world.missing-skill]: the behaviour tree pushes 'objectdrop'");
    }

    private static void assertProblem(String world, String expected) {
        try {
            WorldReader.read(world, "w.json", ENV);
            fail("accepted: " + world);
        } catch (WorldException e) {
            assertTrue("expected '" + expected + "' in:\n" + e.getMessage(),
                    e.problems().stream().anyMatch(p -> p.contains(expected)));
        }
    }
}
