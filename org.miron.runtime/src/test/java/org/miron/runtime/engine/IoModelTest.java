package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.runtime.EngineFixture;

/** io.json loading and the initial parameter values the engine feeds (docs/io-json.md). */
public class IoModelTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private IoModel load() throws Exception {
        EngineFixture f = new EngineFixture(tmp.getRoot().toPath());
        return IoModel.load(f.ioJson);
    }

    @Test
    public void loadsTheTestModel() throws Exception {
        IoModel m = load();
        assertEquals("testbot", m.model());
        assertTrue(Files.isRegularFile(m.mzn()));
        assertEquals(4, m.inputs().size());
        VariationPoint task = m.varpoint("task").get();
        assertEquals(3, (int) task.preset());
        assertEquals("bt", task.bindingType());
        VariationPoint v = m.varpoint("maxVelocity").get();
        assertEquals(91, v.values().size());
        assertEquals("transvel", v.binding().text("parameter"));
        assertNull(v.preset());
    }

    @Test
    public void initialParametersFollowTheContract() throws Exception {
        Map<String, Object> p = new InputState(load()).snapshot().params();
        assertEquals(0.5, p.get("metric_Intralogistics_power_autonomy"));
        assertEquals(0.0, p.get("context_Intralogistics_BatteryLevel"));
        assertEquals(false, p.get("context_Intralogistics_BatteryLevel_known"));
        assertEquals(0, p.get("context_Intralogistics_Space"));
        assertEquals(false, p.get("task_input"));
        assertEquals(0, p.get("task_input_value"));
        assertEquals(-1, p.get("task_current"));
    }

    @Test
    public void inputsOnlyBumpTheVersionWhenSomethingChanged() throws Exception {
        IoModel m = load();
        InputState s = new InputState(m);
        InputSpec power = m.inputs().get(0);
        long v0 = s.version();
        s.setMetric(power, 0.5); // the initial value
        assertEquals(v0, s.version());
        s.setMetric(power, 0.2);
        s.setMetric(power, 0.1);
        assertEquals(v0 + 2, s.version());
        s.setCurrent(m.varpoint("task").get(), 2); // bookkeeping, not an input
        assertEquals(v0 + 2, s.version());
        assertEquals(0.1, s.snapshot().params().get(power.param()));
    }

    @Test
    public void rejectsInvalidFiles() throws Exception {
        Path dir = tmp.getRoot().toPath();
        new EngineFixture(dir);
        String good = Files.readString(dir.resolve("testbot.io.json"));
        String[][] cases = {
            {"\"preset\": 3", "\"preset\": 9", "preset 9"},
            {"\"kind\": \"enum\"", "\"kind\": \"set\"", "kind 'set'"},
            {"\"mzn\": \"testbot.mzn\"", "\"mzn\": \"nope.mzn\"", "nope.mzn"},
            {"\"decision\": \"task_var\",", "", "missing field 'decision'"},
        };
        for (String[] c : cases) {
            assertTrue("fixture contains " + c[0], good.contains(c[0]));
            Path bad = dir.resolve("bad.io.json");
            Files.writeString(bad, good.replace(c[0], c[1]));
            try {
                IoModel.load(bad);
                fail("accepted " + c[1]);
            } catch (IllegalArgumentException e) {
                assertTrue(e.getMessage(), e.getMessage().contains(c[2]));
            }
        }
        assertFalse(Files.readString(dir.resolve("testbot.io.json")).isEmpty());
    }
}
