package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.util.List;
import java.util.Optional;
import org.junit.After;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.skill.ParameterChange;
import org.miron.testkit.runtime.EngineFixture;

/**
 * A boolean varpoint bound to a SmartSoft Boolean parameter (speakerbot model, real minizinc,
 * loopback sockets): the 0/1 the solver decides never leaves the engine; the decision, the
 * decision log and the change-parameter the skill interface applies say false/true.
 */
public class EngineBooleanTest {
    private static final String TAG = "COMMHRI.SPEECHPARAMS.ENABLED";

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private EngineFixture f;

    @Before
    public void setUp() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath(), "speakerbot");
        f.startInfrastructure().startSkills().startEngine(f.options());
    }

    @After
    public void tearDown() {
        f.close();
    }

    private Optional<ParameterChange> awaitEnabled(boolean enabled) throws InterruptedException {
        return f.skills.awaitChange(c -> c.tag().equals(TAG) && c.values().path("1").isBoolean()
                && c.values().path("1").asBoolean() == enabled, EngineFixture.TIMEOUT);
    }

    @Test
    public void theSkillInterfaceIsToldTrueOrFalseNeverANumber() throws Exception {
        ParameterChange quiet = awaitEnabled(false).orElseThrow(() -> new AssertionError(f.skills.history().toString()));
        assertEquals(List.of(TAG + " false false", "COMMIT"), quiet.commands());
        assertEquals("SmartSpeechServer", quiet.component());

        f.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"\",\"value\":0.3}");
        ParameterChange loud = awaitEnabled(true).orElseThrow(() -> new AssertionError(f.skills.history().toString()));
        assertEquals(List.of(TAG + " true true", "COMMIT"), loud.commands());
        assertEquals(Json.MAPPER.readTree("{\"1\":true,\"2\":true}"), f.skills.committed(TAG).orElseThrow());
        for (ParameterChange c : f.skills.history()) {
            c.values().forEach(v -> assertTrue("a JSON boolean, not " + v, v.isBoolean()));
        }
    }

    @Test
    public void decisionsAndTheDecisionLogSayFalseAndTrue() throws Exception {
        JsonNode first = f.probe.await(Topics.DECISION, d -> d.path("changed").toString().contains("sounds"),
                EngineFixture.TIMEOUT);
        assertNotNull("first decision", first);
        assertEquals(Json.MAPPER.readTree("false"), first.path("decisions").path("sounds"));
        assertTrue("nothing applied before the first decision", first.path("inputs").path("sounds_current").isNull());
        assertEquals(Json.MAPPER.readTree("false"), first.path("inputs").path("sounds_input_value"));

        f.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"\",\"value\":0.3}");
        JsonNode loud = f.probe.await(Topics.DECISION, d -> d.path("decisions").path("sounds").isBoolean()
                && d.path("decisions").path("sounds").asBoolean(), EngineFixture.TIMEOUT);
        assertNotNull("sounds on when safety is low", loud);
        assertEquals("applied before this solve", Json.MAPPER.readTree("false"), loud.path("inputs").path("sounds_current"));
        assertNotNull(f.awaitStatus(s -> s.path("applied").path("sounds").isBoolean()
                && s.path("applied").path("sounds").asBoolean()));

        List<String> log = Files.readAllLines(f.dir.resolve("decisions.jsonl"));
        assertTrue(log.toString(), log.size() >= 2);
        for (String line : log) {
            JsonNode entry = Json.MAPPER.readTree(line);
            assertTrue(line, entry.path("decisions").path("sounds").isBoolean());
            JsonNode current = entry.path("inputs").path("sounds_current");
            assertTrue(line, current.isBoolean() || current.isNull());
            assertTrue(line, entry.path("inputs").path("sounds_input_value").isBoolean());
        }
    }

    @Test
    public void anOverrideIsTrueOrFalseAndZeroOrOneIsRefused() throws Exception {
        assertTrue(awaitEnabled(false).isPresent());
        f.publish(Topics.OVERRIDE_PREFIX + "sounds", "{\"value\":1}");
        assertNotNull("1 is not a value of a boolean varpoint",
                f.awaitStatus(s -> s.path("counters").path("badTypeInput").asLong() == 1));
        assertFalse(f.skills.history().stream().anyMatch(c -> c.values().path("1").asBoolean(false)));

        f.publish(Topics.OVERRIDE_PREFIX + "sounds", "{\"value\":true}");
        assertTrue("pinned to true", awaitEnabled(true).isPresent());
        JsonNode pinned = f.probe.await(Topics.DECISION, d -> d.path("inputs").path("sounds_input").asBoolean(),
                EngineFixture.TIMEOUT);
        assertNotNull(pinned);
        assertEquals(Json.MAPPER.readTree("true"), pinned.path("inputs").path("sounds_input_value"));
    }
}
