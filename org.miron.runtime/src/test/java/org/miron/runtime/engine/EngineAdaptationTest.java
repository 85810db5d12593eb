package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.util.List;
import java.util.Optional;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.skill.ParameterChange;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/** End to end over real sockets and the real minizinc: inputs in, adaptations out. */
public class EngineAdaptationTest {
    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;

    @Before
    public void setUp() throws Exception {
        f = fixtures.create();
        f.startAll();
    }


    @Test
    public void batteryDropSwitchesTaskToDock() throws Exception {
        f.estimate("power_autonomy", 0.2);
        JsonNode v = f.awaitVariant("task", "dock");
        assertNotNull("miron.variant.task = dock", v);
        assertEquals("task", v.path("varpoint").asText());
        assertEquals("dock", f.engine.applied().get("task").toString().replace("\"", ""));
    }

    @Test
    public void safetyDropSendsTransvelToTheSkillInterface() throws Exception {
        // initial decision: safety 0.5 -> 10 + 45
        Optional<ParameterChange> first = f.skills.awaitChange(c -> c.value() == 55.0, EngineFixture.TIMEOUT);
        assertTrue("initial transvel 55 arrives", first.isPresent());
        f.estimate("safety", 0.2);
        Optional<ParameterChange> slow = f.skills.awaitChange(c -> c.value() == 28.0, EngineFixture.TIMEOUT);
        assertTrue("transvel 28 arrives after safety drops", slow.isPresent());
        ParameterChange c = slow.get();
        assertEquals("transvel", c.parameter());
        assertEquals("SmartCdServer", c.component());
        assertEquals("COMMNAVIGATIONOBJECTS.CDPARAMETER.TRANSVEL", c.tag());
        assertEquals(List.of("COMMNAVIGATIONOBJECTS.CDPARAMETER.TRANSVEL 28.0 28.0", "COMMIT"), c.commands());
        assertEquals(28.0, f.skills.committed(c.tag()).get().path("1").asDouble(), 0.0);
        assertTrue("acknowledged", poll(() -> f.engine.status().get("paramAcked") >= 2));
    }

    @Test
    public void lateSubscriberGetsTheCurrentDecision() throws Exception {
        f.estimate("power_autonomy", 0.1);
        assertNotNull(f.awaitVariant("task", "dock"));
        try (BusProbe late = new BusProbe(f.endpoints.busOut(), Topics.VARIANT_PREFIX)) {
            JsonNode v = late.await(Topics.VARIANT_PREFIX + "task", b -> true, EngineFixture.TIMEOUT);
            assertNotNull("late joiner receives the cached decision", v);
            assertEquals("dock", v.path("value").asText());
        }
    }

    @Test
    public void overridePinsAndReleasesAVarpoint() throws Exception {
        f.publish(Topics.OVERRIDE_PREFIX + "task", "{\"value\":\"pick\"}");
        assertNotNull("override applied", f.awaitVariant("task", "pick"));
        f.estimate("power_autonomy", 0.1); // would dock, but the override wins
        assertTrue(poll(() -> f.engine.status().get("solved") >= 3));
        assertEquals("\"pick\"", f.engine.applied().get("task").toString());
        f.publish(Topics.OVERRIDE_PREFIX + "task", "{\"value\":null}");
        assertNotNull("released: the rules decide again", f.awaitVariant("task", "dock"));
    }

    @Test
    public void coalescesBurstsAndUsesTheLatestValue() throws Exception {
        long before = f.engine.status().get("solves");
        for (int i = 0; i < 40; i++) {
            f.estimate("safety", 0.9 - i * 0.01); // ends at 0.51
        }
        f.estimate("safety", 0.3); // -> 10 + 27 = 37
        assertTrue("latest value decides", f.skills.awaitChange(c -> c.value() == 37.0, EngineFixture.TIMEOUT).isPresent());
        long solves = f.engine.status().get("solves") - before;
        assertTrue("41 inputs coalesced into fewer solves, not queued: " + solves, solves < 41);
    }

    @Test
    public void statusIsPublishedAsAHeartbeat() throws Exception {
        long solves = f.engine.status().get("solves"); // quiet from now on: no more inputs
        assertTrue("a status without a solve in between", poll(() -> f.probe.messages(Topics.STATUS).stream()
                .filter(m -> m.body().path("counters").path("solves").asLong() == solves).count() >= 2));
        assertEquals(solves, f.engine.status().get("solves"));
    }

    @Test
    public void decisionsAreLoggedAsJsonLines() throws Exception {
        f.estimate("power_autonomy", 0.2);
        assertNotNull(f.awaitVariant("task", "dock"));
        // The engine publishes the variant before it appends the log line: wait for the line.
        assertTrue(poll(() -> lines().size() >= 2 && lines().get(lines().size() - 1).contains("\"dock\"")));
        JsonNode last = Json.MAPPER.readTree(lines().get(lines().size() - 1));
        assertEquals("SOLVED", last.path("outcome").asText());
        assertEquals("minizinc", last.path("backend").asText());
        assertEquals("dock", last.path("decisions").path("task").asText());
        assertEquals(0.2, last.path("inputs").path("metric_Intralogistics_power_autonomy").asDouble(), 0.0);
        assertTrue(last.has("solveMs"));
        JsonNode decision = f.probe.await(Topics.DECISION, d -> d.path("decisions").path("task").asText().equals("dock"),
                EngineFixture.TIMEOUT);
        assertNotNull("miron.decision published", decision);
    }

    private List<String> lines() {
        try {
            return Files.readAllLines(f.dir.resolve("decisions.jsonl"));
        } catch (java.io.IOException e) {
            return List.of();
        }
    }

    static boolean poll(java.util.function.BooleanSupplier condition) throws InterruptedException {
        long end = System.currentTimeMillis() + EngineFixture.TIMEOUT;
        while (System.currentTimeMillis() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(20);
        }
        return condition.getAsBoolean();
    }
}
