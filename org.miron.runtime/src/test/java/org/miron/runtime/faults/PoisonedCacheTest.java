package org.miron.runtime.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/**
 * Issue 10, item 2: a valid estimate followed by invalid ones for the same name (out of range,
 * wrong type, trailing garbage) must leave the valid one in the broker's cache, so an engine
 * (re)started afterwards still decides from it.
 */
public class PoisonedCacheTest {
    private static final String BAD_ESTIMATES[] = {
        "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":7}",
        "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":\"low\"}",
        "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.9}xyz",
    };
    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;

    @Test
    public void invalidEstimatesNeverReplaceTheCachedValidOne() throws Exception {
        f = fixtures.create();
        f.startInfrastructure().startSkills();
        f.estimate("power_autonomy", 0.2);
        for (String bad : BAD_ESTIMATES) {
            f.publish(Topics.ESTIMATE, bad);
        }
        f.publish(Topics.CONTEXT, "{\"name\":\"Space\",\"namespace\":\"Intralogistics\",\"type\":\"enum\",\"value\":\"HIGH\"}");
        f.publish(Topics.CONTEXT, "{\"name\":\"Space\",\"namespace\":\"Intralogistics\",\"type\":\"enum\",\"value\":3}");
        assertTrue(f.input.flush(EngineFixture.TIMEOUT));
        long end = System.currentTimeMillis() + EngineFixture.TIMEOUT;
        while (f.broker.refusedByCache() < BAD_ESTIMATES.length + 1 && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertEquals("every invalid message was seen and refused", BAD_ESTIMATES.length + 1, f.broker.refusedByCache());

        try (BusProbe late = new BusProbe(f.endpoints.busOut(), "roqme.")) {
            JsonNode power = late.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy"),
                    EngineFixture.TIMEOUT);
            assertNotNull("replayed", power);
            assertEquals("the valid value is the cached one", 0.2, power.path("value").asDouble(), 0.0);
            JsonNode space = late.await(Topics.CONTEXT, b -> b.path("name").asText().equals("Space"), EngineFixture.TIMEOUT);
            assertEquals("HIGH", space.path("value").asText());
        }

        // an engine started now gets only the good estimate and docks
        f.startEngine(f.options());
        assertNotNull("engine decides from the cached valid estimate", f.awaitVariant("task", "dock"));
        assertEquals("nothing bad reached the new engine", 0, f.engine.status().get("badTypeInput")
                + f.engine.status().get("malformedInput"));
    }
}
