package org.miron.runtime.engine;

import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/** The skill interface starts after the engine: change-parameter is retried until acknowledged. */
public class ParameterRetryTest {
    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;

    @Test
    public void unacknowledgedChangesAreRetriedWithoutBlockingTheEngine() throws Exception {
        f = fixtures.create();
        f.startInfrastructure().startEngine(f.options());
        assertNotNull("variants flow while the skill interface is down", f.awaitVariant("task", "pickDeliverCharge"));
        assertNotNull("missing acks are reported", f.awaitStatus(s -> s.path("counters").path("paramRetries").asLong() >= 2
                && s.path("lastError").path("kind").asText().equals("parameter")));
        f.estimate("power_autonomy", 0.2);
        assertNotNull("the engine keeps adapting", f.awaitVariant("task", "dock"));
        f.estimate("safety", 0.2); // supersedes the pending 55
        assertNotNull(f.probe.await(Topics.DECISION, d -> d.path("decisions").path("maxVelocity").asInt() == 28,
                EngineFixture.TIMEOUT));
        f.startSkills();
        assertTrue(f.skills.awaitChange(c -> c.value() == 28.0, EngineFixture.TIMEOUT).isPresent());
        assertTrue("stale values are neither queued nor replayed: " + f.skills.history(),
                f.skills.history().stream().allMatch(c -> c.value() == 28.0));
    }
}
