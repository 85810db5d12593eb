package org.miron.runtime.live;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.Test;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;

/**
 * The executor's side of {@code miron.blackboard.<vp>} over a real broker: numbers and the
 * true/false of a boolean varpoint reach the blackboard source; anything else is dropped and counted.
 */
public class DecisionFeedTest {
    private static final long TIMEOUT = 20_000;

    @Test
    public void booleanAndNumericBlackboardDecisionsArriveAsTheyWereDecided() throws Exception {
        Endpoints endpoints = Endpoints.freeLoopback();
        VariantSource variants = new VariantSource();
        VariantSource blackboard = new VariantSource();
        try (Broker broker = new Broker(endpoints).start();
                BusClient engine = new BusClient("fake-engine", endpoints.busIn(), null, List.of(), (t, b) -> { })
                        .start();
                DecisionFeed feed = new DecisionFeed(endpoints.busIn(), endpoints.busOut(), variants, blackboard)
                        .start()) {
            assertTrue(engine.awaitReady(TIMEOUT));
            // Retained, so a feed that subscribes late still gets them from the broker's cache.
            engine.publishRetained(Topics.BLACKBOARD_PREFIX + "mute", Topics.BLACKBOARD_PREFIX + "mute",
                    "{\"varpoint\":\"mute\",\"value\":true,\"seq\":1}");
            engine.publishRetained(Topics.BLACKBOARD_PREFIX + "speed", Topics.BLACKBOARD_PREFIX + "speed",
                    "{\"varpoint\":\"speed\",\"value\":0.25,\"seq\":1}");
            engine.publishRetained(Topics.BLACKBOARD_PREFIX + "mode", Topics.BLACKBOARD_PREFIX + "mode",
                    "{\"varpoint\":\"mode\",\"value\":\"fast\",\"seq\":1}");
            long end = System.currentTimeMillis() + TIMEOUT;
            while ((blackboard.current("mute").isEmpty() || blackboard.current("speed").isEmpty()
                    || feed.rejectedCount() == 0) && System.currentTimeMillis() < end) {
                Thread.sleep(10);
            }
            assertEquals(Optional.of(Boolean.TRUE), blackboard.current("mute"));
            assertEquals(Optional.of(0.25), blackboard.current("speed"));
            assertEquals(Optional.empty(), blackboard.current("mode"));
            // Live and again from the cache when the subscription lands after it (docs/wire-formats.md).
            assertTrue(feed.rejectedCount() >= 1);
        }
    }
}
