package org.miron.runtime.requirement;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.miron.runtime.requirement.Traces.always;
import static org.miron.runtime.requirement.Traces.cmp;
import static org.miron.runtime.requirement.Traces.eventually;
import static org.miron.runtime.requirement.Traces.implies;
import static org.miron.runtime.requirement.Traces.is;
import static org.miron.runtime.requirement.Traces.modeIs;
import static org.miron.runtime.requirement.Traces.state;
import static org.miron.runtime.requirement.Traces.temporal;
import static org.miron.runtime.requirement.Traces.x;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import org.junit.After;
import org.junit.Test;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;

/** The monitors on a live loopback bus: what they read, what they publish, bad input, the timer. */
public class LiveRequirementsTest {
    private static final long TIMEOUT = 20_000;
    private final Endpoints endpoints = Endpoints.freeLoopback();
    private final AtomicLong clock = new AtomicLong();
    private Broker broker;
    private BusProbe probe;
    private BusClient input;
    private LiveRequirements live;

    private void start(com.fasterxml.jackson.databind.JsonNode... formulas) throws InterruptedException {
        broker = new Broker(endpoints).start();
        probe = new BusProbe(endpoints.busOut(), "miron.requirement");
        input = new BusClient("test-input", endpoints.busIn(), null, List.of(), (t, b) -> {
        }).start();
        assertTrue("test publisher reaches the broker", input.awaitReady(TIMEOUT));
        live = new LiveRequirements(RequirementModel.parse(Traces.model(formulas)), endpoints.busIn(), endpoints.busOut())
                .clock(clock::get).statusInterval(200).start();
        assertTrue("the monitors subscribe", live.awaitSubscribed(TIMEOUT));
    }

    @After
    public void close() {
        for (AutoCloseable c : new AutoCloseable[] {live, input, probe, broker}) {
            if (c != null) {
                try {
                    c.close();
                } catch (Exception ignored) {
                    // best effort
                }
            }
        }
    }

    private void context(String name, String type, Object value) {
        String v = value instanceof String s ? "\"" + s + "\"" : String.valueOf(value);
        input.publish(Topics.CONTEXT, "{\"name\":\"" + name + "\",\"namespace\":\"T\",\"type\":\"" + type + "\",\"value\":"
                + v + ",\"time\":1}");
    }

    private JsonNode awaitEvent(String name, String verdict) throws InterruptedException {
        return probe.await(Topics.REQUIREMENT, b -> b.path("name").asText().equals(name)
                && b.path("verdict").asText().equals(verdict), TIMEOUT);
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (!condition.getAsBoolean()) {
            assertTrue(what, System.currentTimeMillis() < end);
            Thread.sleep(5);
        }
    }

    @Test
    public void contextsEstimatesAndAppliedDecisionsAreCheckedAndEachEventPublishedWithItsValues() throws Exception {
        start(always(x("<", 5)), always(modeIs(0)), temporal("never", null, state(cmp(">", "p", 0.8))));
        clock.set(1000);
        context("x", "number", 1.0);
        await("x taken", () -> live.contextsIn() == 1);
        clock.set(2500);
        context("x", "number", 7.0);
        await("x taken", () -> live.contextsIn() == 2);
        clock.set(2600); // the values of an instant are judged once time moves on
        JsonNode v = awaitEvent("r0", "violated");
        assertNotNull("x >= 5 is told", v);
        assertEquals(2.5, v.path("time").asDouble(), 1e-9);
        assertEquals(7.0, v.path("values").path("x").asDouble(), 1e-9);
        clock.set(3000);
        context("x", "number", 2.0);
        await("x taken", () -> live.contextsIn() == 3);
        clock.set(3100);
        JsonNode met = awaitEvent("r0", "met");
        assertNotNull("met again is told", met);
        assertEquals(3.0, met.path("time").asDouble(), 1e-9);

        clock.set(4000);
        input.publish(Topics.DECISION, "{\"seq\":3,\"decisions\":{\"mode\":\"fast\",\"other\":12}}");
        await("the decision taken", () -> live.decisionsIn() == 1);
        clock.set(4100);
        JsonNode fast = awaitEvent("r1", "violated");
        assertNotNull("the applied decision is checked", fast);
        assertEquals("fast", fast.path("values").path("mode").asText());
        assertEquals(4.0, fast.path("time").asDouble(), 1e-9);

        clock.set(5000);
        input.publish(Topics.ESTIMATE, "{\"name\":\"p\",\"namespace\":\"T\",\"value\":0.9,\"time\":1}");
        await("the estimate taken", () -> live.estimatesIn() == 1);
        clock.set(5100);
        JsonNode high = awaitEvent("r2", "violated");
        assertNotNull("the estimate is checked", high);
        assertEquals(0.9, high.path("values").path("p").asDouble(), 1e-9);

        clock.set(6000);
        List<RequirementResult> results = live.finish();
        assertEquals(List.of("violated", "violated", "violated"), Traces.verdicts(results));
        assertEquals(1, results.get(0).violations());
        JsonNode status = probe.await(Topics.REQUIREMENT_STATUS, b -> b.path("state").asText().equals("finished"), TIMEOUT);
        assertNotNull("a final status", status);
        assertEquals(6.0, status.path("time").asDouble(), 1e-9);
        assertEquals("violated", status.path("requirements").path("r0").path("verdict").asText());
        assertEquals(1, status.path("requirements").path("r0").path("violations").asInt());
        assertEquals(3, status.path("counters").path("contextsIn").asInt());
        assertEquals(1, status.path("counters").path("estimatesIn").asInt());
        assertEquals(1, status.path("counters").path("decisionsIn").asInt());
        assertEquals(0, status.path("counters").path("badBusInput").asInt());
    }

    @Test
    public void aDeadlinePassingWithoutAnyMessageIsDetectedByTheTimer() throws Exception {
        start(always(implies(is("a"), eventually(300, is("b")))));
        clock.set(100);
        context("b", "boolean", false);
        context("a", "boolean", true);
        await("a and b taken", () -> live.contextsIn() == 2);
        Thread.sleep(3 * LiveRequirements.TICK_MS); // still within the deadline: nothing to tell
        assertTrue(probe.messages(Topics.REQUIREMENT).isEmpty());
        clock.set(1000); // no message from now on: only the timer can see the deadline pass
        JsonNode late = awaitEvent("r0", "violated");
        assertNotNull("the missed deadline is told", late);
        assertEquals("violated at the instant the obligation opened", 0.1, late.path("time").asDouble(), 1e-9);
        assertEquals("known when the clock passed the deadline", 1.0, late.path("detected").asDouble(), 1e-9);
        assertTrue(late.path("values").path("a").asBoolean());
    }

    @Test
    public void badBusInputIsCountedAndUnreadOrMissingSignalsAreNotChecked() throws Exception {
        start(always(x("<", 5)), always(is("a")));
        input.publish(Topics.CONTEXT, "not json");
        input.publish(Topics.CONTEXT, "{\"value\":3}"); // no name
        input.publish(Topics.ESTIMATE, "{\"name\":\"p\",\"value\":\"high\"}"); // not a number
        input.publish(Topics.DECISION, "{\"seq\":1}"); // no decisions
        context("Unread", "number", 3); // a context no requirement reads: passed over
        context("x", "number", "seven"); // a value the signal cannot take
        context("x", "number", 1);
        // The status is periodic on the component's clock, which only this test moves: move it on until
        // a status that has taken every message comes (the first one may go out before they arrive).
        JsonNode status = null;
        for (long t = 0; status == null && t < 1900; t += 10) {
            clock.set(t);
            status = probe.await(Topics.REQUIREMENT_STATUS, b -> b.path("counters").path("badBusInput").asInt() == 4
                    && b.path("counters").path("contextsIn").asInt() == 3, 50);
        }
        assertNotNull("bad input counted, good input still taken", status);
        assertEquals(1, status.path("counters").path("rejected").asInt());
        assertEquals("holds", status.path("requirements").path("r0").path("verdict").asText());
        assertEquals("a never arrived", "not-evaluated", status.path("requirements").path("r1").path("verdict").asText());
        clock.set(2000);
        List<RequirementResult> results = live.finish();
        assertEquals(List.of("holds", "not-evaluated"), Traces.verdicts(results));
        assertTrue(probe.messages(Topics.REQUIREMENT).isEmpty());
    }
}
