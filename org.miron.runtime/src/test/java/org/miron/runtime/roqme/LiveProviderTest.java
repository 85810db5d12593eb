package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import org.junit.After;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;

/** The provider on a real broker over loopback: estimates, observations, bad input, restart, and with the engine. */
public class LiveProviderTest {
    private static final long TIMEOUT = 20_000;
    private static final long PERIOD = 100;

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private Endpoints ep;
    private Broker broker;
    private BusProbe probe;
    private BusClient input;
    private LiveProvider provider;
    private CompiledModel model;

    @Before
    public void setUp() throws Exception {
        model = RoqmeFixtures.compile(RoqmeFixtures.resource("intralogistics.roqme.json"));
    }

    private void startBus() throws InterruptedException {
        ep = Endpoints.freeLoopback();
        broker = new Broker(ep).start();
        probe = new BusProbe(ep.busOut(), "roqme.");
        input = new BusClient("test-input", ep.busIn(), null, List.of(), (t, b) -> { }).start();
        assertTrue(input.awaitReady(TIMEOUT));
    }

    @After
    public void tearDown() {
        for (AutoCloseable c : new AutoCloseable[] {provider, input, probe, broker}) {
            try {
                if (c != null) {
                    c.close();
                }
            } catch (Exception ignored) {
                // best effort
            }
        }
    }

    private static final java.util.concurrent.atomic.AtomicLong SAMPLE_TIME = new java.util.concurrent.atomic.AtomicLong(System.currentTimeMillis());

    /**
     * A context sample with a time of its own, as a robot's monitor sends them: the broker may
     * replay its cached copy to us when anyone subscribes (see BusProxy), and only the time tells
     * that copy from a new sample, so counts stay exact however the subscriptions interleave.
     */
    private static String context(String name, String type, String value) {
        return "{\"name\":\"" + name + "\",\"namespace\":\"Intralogistics\",\"type\":\"" + type + "\",\"value\":" + value
                + ",\"time\":" + SAMPLE_TIME.incrementAndGet() + "}";
    }

    @Test
    public void publishesEstimatesEveryPeriodAndFiredObservations() throws Exception {
        startBus();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(provider.awaitReady(TIMEOUT));
        JsonNode safety = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("safety"), TIMEOUT);
        assertEquals(0.7, safety.path("value").asDouble(), 1e-12); // its reference: no evidence yet
        assertEquals("Intralogistics", safety.path("namespace").asText());
        assertTrue(safety.path("time").asLong() > 0);
        // the provider's subscription is live once a context it receives shows up in its status
        awaitAccepted("BatteryLevel", "number", "50");
        input.publish(Topics.CONTEXT, context("BatteryLevel", "number", "20"));
        JsonNode fired = probe.await(Topics.OBSERVATION, b -> b.path("name").asText().equals("batteryLow"), TIMEOUT);
        assertNotNull("roqme.observation batteryLow", fired);
        assertEquals("undermines", fired.path("actions").path(0).path("kind").asText());
        assertEquals("power_autonomy", fired.path("actions").path(0).path("belief").asText());
        assertEquals("VERYHIGH", fired.path("actions").path(0).path("strength").asText());
        JsonNode low = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy")
                && b.path("value").asDouble() < 0.1, TIMEOUT);
        assertEquals(2 * (1 / 11.0) * 0.5, low.path("value").asDouble(), 1e-3); // r = 10, decayed by at most a tick
    }

    private void awaitAccepted(String name, String type, String value) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        long before = provider.contexts();
        while (provider.contexts() == before && System.currentTimeMillis() < end) {
            input.publish(Topics.CONTEXT, context(name, type, value));
            Thread.sleep(50);
        }
        assertTrue("the provider receives contexts", provider.contexts() > before);
    }

    /**
     * A late subscriber to the contexts makes the broker replay its cache through every matching
     * pipe: the provider gets a copy of the last sample, the same body, which it must not count
     * again (it would break a trend window or count an update twice).
     */
    @Test
    public void theBrokersReplayedCopyOfASampleCountsOnce() throws Exception {
        startBus();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(provider.awaitSubscribed(TIMEOUT));
        String sample = "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":50,\"time\":1}";
        input.publish(Topics.CONTEXT, sample);
        long end = System.currentTimeMillis() + TIMEOUT;
        while (provider.contexts() == 0 && System.currentTimeMillis() < end) {
            Thread.sleep(20);
        }
        assertEquals(1, provider.contexts());
        try (BusProbe late = new BusProbe(ep.busOut(), Topics.CONTEXT)) {
            assertNotNull("the late subscriber gets the replay", late.await(Topics.CONTEXT, b -> b.path("time").asLong() == 1, TIMEOUT));
            input.publish(Topics.CONTEXT, sample.replace("\"time\":1", "\"time\":2"));
            assertNotNull(late.await(Topics.CONTEXT, b -> b.path("time").asLong() == 2, TIMEOUT));
            Thread.sleep(300); // the provider's copy of the replay came before the second sample
            assertEquals("the replayed copy is dropped, the new sample counts", 2, provider.contexts());
        }
    }

    @Test
    public void badContextsAreCountedReportedAndDropped() throws Exception {
        startBus();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(provider.awaitReady(TIMEOUT));
        awaitAccepted("BatteryLevel", "number", "50");
        input.publish(Topics.CONTEXT, "{not json");
        input.publish(Topics.CONTEXT, context("Altitude", "number", "3"));
        input.publish(Topics.CONTEXT, context("BatteryLevel", "boolean", "true"));
        input.publish(Topics.CONTEXT, context("FreeSpace", "enum", "\"HUGE\""));
        input.publish(Topics.CONTEXT, context("BatteryLevel", "number", "\"twenty\""));
        JsonNode st = probe.await(Topics.ROQME_STATUS, b -> b.path("counters").path("badTypeInput").asLong() == 3
                && b.path("counters").path("malformedInput").asLong() == 1
                && b.path("counters").path("unknownInput").asLong() == 1, TIMEOUT);
        assertNotNull("roqme.status counts the bad contexts", st);
        assertEquals("intralogistics", st.path("model").asText());
        assertTrue(st.path("lastError").path("message").asText(), st.path("lastError").path("message").asText().contains("BatteryLevel"));
        // still working
        input.publish(Topics.CONTEXT, context("FreeSpace", "enum", "\"HIGH\""));
        input.publish(Topics.CONTEXT, context("ObstacleDistance", "number", "5"));
        assertNotNull(probe.await(Topics.OBSERVATION, b -> b.path("name").asText().equals("openSpace"), TIMEOUT));
        assertEquals(5, provider.rejected());
    }

    /** The engine reads derived contexts (a MIRoN rule on qos.HumanNearby): the provider publishes them on change. */
    @Test
    public void derivedContextsArePublishedOnChangeAndNotTakenBackAsInputs() throws Exception {
        startBus();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(provider.awaitReady(TIMEOUT));
        awaitAccepted("BatteryLevel", "number", "50");
        long before = provider.contexts();
        input.publish(Topics.CONTEXT, context("HumanDistance", "number", "0.5"));
        JsonNode near = probe.await(Topics.CONTEXT, b -> b.path("name").asText().equals("HumanNearby"), TIMEOUT);
        assertNotNull("HumanNearby published once HumanDistance is known", near);
        assertTrue(near.path("value").asBoolean(false));
        assertTrue(near.path("derived").asBoolean(false));
        assertEquals("Intralogistics", near.path("namespace").asText());
        assertEquals("boolean", near.path("type").asText());
        input.publish(Topics.CONTEXT, context("HumanDistance", "number", "0.7")); // still near: nothing new
        input.publish(Topics.CONTEXT, context("HumanDistance", "number", "3"));
        assertNotNull(probe.await(Topics.CONTEXT, b -> b.path("name").asText().equals("HumanNearby")
                && b.path("value").isBoolean() && !b.path("value").asBoolean(), TIMEOUT));
        long end = System.currentTimeMillis() + TIMEOUT;
        while (provider.contexts() < before + 3 && System.currentTimeMillis() < end) {
            Thread.sleep(20);
        }
        assertEquals("the three samples count, our own HumanNearby copies do not", before + 3, provider.contexts());
        assertEquals("one publication per change (a cache replay repeats a body: counted once)", 2, probe.messages(Topics.CONTEXT).stream()
                .filter(m -> m.body().path("name").asText().equals("HumanNearby")).map(m -> m.body().toString()).distinct().count());
        assertEquals(0, provider.rejected());
        // from anyone else, a derived context is no input: refused, and the message says why
        input.publish(Topics.CONTEXT, context("HumanNearby", "boolean", "true"));
        JsonNode st = probe.await(Topics.ROQME_STATUS, b -> b.path("counters").path("unknownInput").asLong() == 1, TIMEOUT);
        assertNotNull(st);
        assertTrue(st.path("lastError").path("message").asText(), st.path("lastError").path("message").asText().contains("derived"));
    }

    @Test
    public void restartedProviderResumesEstimatesWithinTwoPeriodsWithTheCachedContexts() throws Exception {
        startBus();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(provider.awaitReady(TIMEOUT));
        awaitAccepted("BatteryLevel", "number", "50");
        input.publish(Topics.CONTEXT, context("HumanDistance", "number", "0.5"));
        assertNotNull(probe.await(Topics.OBSERVATION, b -> b.path("name").asText().equals("tooClose"), TIMEOUT));
        provider.close();
        int seen = probe.messages(Topics.OBSERVATION).size();
        long restart = System.currentTimeMillis();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        // the broker's last-value cache gives the new provider the current contexts: tooClose again
        JsonNode again = probe.await(Topics.OBSERVATION, b -> b.path("name").asText().equals("tooClose")
                && b.path("time").asLong() >= restart, TIMEOUT);
        assertNotNull("contexts after restart " + provider.contexts() + " fired " + provider.fired() + " obs " + probe.messages(Topics.OBSERVATION).stream().map(m -> m.body().toString()).toList(), again);
        assertTrue(probe.messages(Topics.OBSERVATION).size() > seen);
        JsonNode est = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("safety")
                && b.path("time").asLong() >= restart, TIMEOUT);
        assertTrue("first estimate " + (est.path("time").asLong() - restart) + " ms after the restart",
                est.path("time").asLong() - restart <= 2 * PERIOD + 1000); // two periods, plus connecting
    }

    @Test
    public void aStateFileKeepsTheEvidenceAcrossARestart() throws Exception {
        startBus();
        java.nio.file.Path state = tmp.getRoot().toPath().resolve("roqme.state.json");
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).state(state).start();
        assertTrue(provider.awaitReady(TIMEOUT));
        awaitAccepted("BatteryLevel", "number", "50");
        input.publish(Topics.CONTEXT, context("BatteryLevel", "number", "20"));
        assertNotNull(probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy")
                && b.path("value").asDouble() < 0.1, TIMEOUT));
        provider.close();
        // the battery is charged meanwhile: batteryLow does not fire again, only the saved evidence can keep the estimate low
        input.publish(Topics.CONTEXT, context("BatteryLevel", "number", "60"));
        Thread.sleep(300);
        long restart = System.currentTimeMillis();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).state(state).start();
        JsonNode first = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy")
                && b.path("time").asLong() >= restart, TIMEOUT);
        assertTrue("restored evidence: " + first, first.path("value").asDouble() < 0.15);
        provider.close();
        // without the file, the same restart starts from the reference
        long plain = System.currentTimeMillis();
        provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
        JsonNode fresh = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy")
                && b.path("time").asLong() >= plain, TIMEOUT);
        assertEquals(0.5, fresh.path("value").asDouble(), 1e-12);
    }

    @Test
    public void anUnreadableStateFileIsAStartUpError() throws Exception {
        java.nio.file.Path state = tmp.getRoot().toPath().resolve("bad.json");
        java.nio.file.Files.writeString(state, "{\"format\":1,\"time\":5,\"beliefs\":{\"safety\":[{\"r\":-1}]}}");
        try {
            new LiveProvider(model, PERIOD, 5000, "tcp://127.0.0.1:1", "tcp://127.0.0.1:1").state(state);
            org.junit.Assert.fail();
        } catch (java.io.IOException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith(state + ": bad evidence of safety"));
        }
    }

    @Test
    public void aContextChangeLeadsTheEngineToAVariant() throws Exception {
        try (EngineFixture f = new EngineFixture(tmp.getRoot().toPath())) {
            f.startAll(); // testbot: task = dock when power_autonomy < 0.3
            ep = f.endpoints;
            // the engine ignores the provider's own topics: only the bogus one, sent last, is unknown input
            long unknown = f.engine.status().get("unknownInput");
            f.publish(Topics.OBSERVATION, "{\"name\":\"batteryLow\",\"namespace\":\"Intralogistics\",\"time\":1,\"actions\":[]}");
            f.publish(Topics.ROQME_STATUS, "{\"time\":1,\"model\":\"intralogistics\",\"state\":\"ok\"}");
            f.publish("roqme.bogus", "{\"name\":\"x\"}");
            long end0 = System.currentTimeMillis() + TIMEOUT;
            while (f.engine.status().get("unknownInput") == unknown && System.currentTimeMillis() < end0) {
                Thread.sleep(10);
            }
            Thread.sleep(200);
            assertEquals(unknown + 1, f.engine.status().get("unknownInput"));
            provider = new LiveProvider(model, PERIOD, 5000, ep.busIn(), ep.busOut()).start();
            assertTrue(provider.awaitReady(TIMEOUT));
            // a low battery, above the engine's own 5 % rule: only the provider's estimate can dock it
            long end = System.currentTimeMillis() + TIMEOUT;
            JsonNode dock = null;
            while (dock == null && System.currentTimeMillis() < end) {
                f.publish(Topics.CONTEXT, context("BatteryLevel", "number", "60"));
                Thread.sleep(3 * PERIOD);
                f.publish(Topics.CONTEXT, context("BatteryLevel", "number", "20"));
                dock = f.probe.await(Topics.VARIANT_PREFIX + "task", b -> "dock".equals(b.path("value").asText()), 2000);
            }
            assertNotNull("miron.variant.task = dock from the provider's power_autonomy", dock);
            assertTrue(provider.fired() > 0);
        }
    }
}
