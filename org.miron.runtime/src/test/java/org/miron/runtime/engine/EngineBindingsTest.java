package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/** btport and decision-only bindings, numeric overrides, empty namespace (portbot model). */
public class EngineBindingsTest {
    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;

    @Before
    public void setUp() throws Exception {
        f = fixtures.create("portbot");
        f.startInfrastructure().startEngine(f.options());
    }


    private JsonNode awaitSpeed(double value) throws InterruptedException {
        return f.probe.await(Topics.BLACKBOARD_PREFIX + "speed", b -> b.path("value").asDouble() == value,
                EngineFixture.TIMEOUT);
    }

    @Test
    public void btportDecisionsGoToTheBlackboardUntruncated() throws Exception {
        JsonNode first = awaitSpeed(0.5);
        assertNotNull("initial speed 0.5", first);
        assertEquals("speed", first.path("varpoint").asText());
        f.input.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"value\":0.3}"); // no namespace: matched by name
        JsonNode slower = awaitSpeed(0.25);
        assertNotNull("speed 0.25, not truncated", slower);
        assertTrue(slower.path("seq").asLong() > first.path("seq").asLong());
    }

    @Test
    public void decisionOnlyVarpointsAppearOnlyInTheDecision() throws Exception {
        f.input.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"\",\"value\":0.2}");
        JsonNode d = f.probe.await(Topics.DECISION, b -> b.path("decisions").path("mode").asInt() == 1
                && b.path("changed").toString().contains("mode"), EngineFixture.TIMEOUT);
        assertNotNull("mode decided", d);
        assertEquals(0.1, d.path("decisions").path("speed").asDouble(), 0.0);
        assertTrue(f.probe.messages(Topics.VARIANT_PREFIX + "mode").isEmpty());
        assertTrue(f.probe.messages(Topics.BLACKBOARD_PREFIX + "mode").isEmpty());
    }

    @Test
    public void numericOverrideIsMatchedByValue() throws Exception {
        assertNotNull(awaitSpeed(0.5));
        f.publish(Topics.OVERRIDE_PREFIX + "speed", "{\"value\":0.1}");
        JsonNode pinned = awaitSpeed(0.1);
        assertNotNull("pinned to 0.1", pinned);
        f.publish(Topics.OVERRIDE_PREFIX + "speed", "{\"value\":0.3}"); // not one of the values
        assertNotNull(f.awaitStatus(s -> s.path("counters").path("badTypeInput").asLong() == 1));
        f.publish(Topics.OVERRIDE_PREFIX + "speed", "{\"value\":null}");
        JsonNode released = f.probe.await(Topics.BLACKBOARD_PREFIX + "speed", b -> b.path("value").asDouble() == 0.5
                && b.path("seq").asLong() > pinned.path("seq").asLong(), EngineFixture.TIMEOUT);
        assertNotNull("released: back to 0.5", released);
    }
}
