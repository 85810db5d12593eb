package org.miron.runtime.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.stream.Collectors;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.IoModel;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.TestbotRules;

/**
 * Issue 10, item 1: a (re)started engine must not publish a decision from its initial values
 * when the broker's cache can give it the current inputs: the robot is charging
 * ({@code power_autonomy = 0.2}), the engine restarts, and no decision may say
 * {@code pickDeliverCharge} in between.
 */
public class EngineRestartTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private EngineFixture f;
    private Engine second;

    @After
    public void tearDown() {
        if (second != null) {
            second.close();
        }
        f.close();
    }

    private Engine engine() {
        return new Engine(IoModel.load(f.ioJson), new TestbotRules(), f.options());
    }

    @Test
    public void aRestartedEngineDecidesFromTheReplayedInputsNotItsDefaults() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        f.startInfrastructure().startSkills();
        f.estimate("power_autonomy", 0.2);
        assertTrue(f.input.flush(EngineFixture.TIMEOUT));
        // the first engine already starts on a cached input
        f.engine = engine().start();
        assertNotNull(f.awaitVariant("task", "dock"));
        f.engine.close();
        f.engine = null;
        int before = f.probe.messages(Topics.DECISION).size();

        second = engine().start();
        assertNotNull("the restarted engine decides", f.probe.await(Topics.DECISION,
                d -> d.path("seq").asLong() == 1 && f.probe.messages(Topics.DECISION).size() > before, EngineFixture.TIMEOUT));
        List<String> tasks = f.probe.messages(Topics.DECISION).stream()
                .map(m -> m.body().path("seq").asLong() + ":" + m.body().path("decisions").path("task").asText())
                .collect(Collectors.toList());
        assertTrue("no decision from the initial values, before or after the restart: " + tasks,
                tasks.stream().allMatch(t -> t.endsWith(":dock")));
        assertEquals("first decision of the new engine", "dock", second.applied().get("task").toString().replace("\"", ""));
        assertTrue(f.probe.messages(Topics.VARIANT_PREFIX + "task").stream()
                .allMatch(m -> m.body().path("value").asText().equals("dock")));
    }
}
