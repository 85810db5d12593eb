package org.miron.runtime.sim;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.runtime.Connect;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.testkit.runtime.BusProbe;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The mock skill interface acting on a world, over its real sockets and a real broker on
 * 127.0.0.1: a move takes the world's time (distance / speed) and drains the battery as the world
 * says, the world's contexts reach the bus, and change-parameter slows the next move down. The
 * world runs 20 times faster than the wall clock.
 */
public class LiveWorldTest {
    private static final long TIMEOUT = 30_000;
    private static final double SCALE = 0.05;
    private static final String WORLD = """
            {
              "places": { "a": { "x": 0, "y": 0 }, "b": { "x": 10, "y": 0 } },
              "start": "a",
              "state": { "battery": { "type": "number", "initial": 50, "min": 0, "max": 100 } },
              "parameters": { "transvel": 100 },
              "events": ["Arrived"],
              "skills": {
                "MoveTo": { "target": { "x": "x", "y": "y" }, "duration": "distance / (transvel / 100)",
                            "perSecond": { "battery": "-1" }, "events": ["Arrived"] },
                "Ping": { "duration": "0" }
              },
              "contexts": { "Battery": { "value": "battery", "every": "1s" }, "Arrived": { "event": "Arrived" } },
              "measures": { "arrivals": { "count": "Arrived" } }
            }
            """;
    private static final WorldEnv ENV = new WorldEnv(Map.of("MoveTo", Set.of("x", "y"), "Ping", Set.of()),
            Map.of("Battery", new RoqmeModel.Type("number", null, null, null, null, null),
                    "Arrived", new RoqmeModel.Type("eventtype", null, null, null, null, null)));

    private final Endpoints ep = Endpoints.freeLoopback();
    private final ZContext ctx = new ZContext();
    private Broker broker;
    private BusProbe probe;
    private SkillInterfaceMock mock;
    private ZMQ.Socket req;
    private ZMQ.Socket results;

    @Before
    public void setUp() throws Exception {
        broker = new Broker(ep).start();
        probe = new BusProbe(ep.busOut(), "roqme.context");
        LiveWorld world = new LiveWorld(WorldReader.read(WORLD, "test.world.json", ENV), 1, SCALE,
                Map.of("Battery", "Test", "Arrived", "Test"), ep.busIn());
        mock = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), world).start();
        world.begin();
        req = ctx.createSocket(SocketType.REQ);
        req.setReceiveTimeOut((int) TIMEOUT);
        req.setLinger(0);
        Connect.connect(req, ep.skill());
        results = ctx.createSocket(SocketType.SUB);
        results.setLinger(0);
        results.subscribe(new byte[0]);
        Connect.connect(results, ep.skillEvents());
    }

    @After
    public void tearDown() {
        mock.close();
        probe.close();
        broker.close();
        ctx.close();
    }

    @Test
    public void skillsTakeTheWorldsTimeAndTheirEffectsReachTheBus() throws Exception {
        JsonNode first = probe.await("roqme.context", b -> b.path("name").asText().equals("Battery"), TIMEOUT);
        assertNotNull("the world publishes its battery", first);
        assertEquals("Test", first.path("namespace").asText());
        assertEquals("number", first.path("type").asText());
        assertEquals(50.0, first.path("value").asDouble(), 1e-9); // nothing drains it before a skill runs
        awaitSubscriberConnected();

        // 10 m at 1 m/s: 10 s of world time, 0.5 s here; 1 %/s of battery while it runs
        long t0 = System.nanoTime();
        JsonNode r1 = push(1, "{\"x\": 10, \"y\": 0}");
        long ms1 = (System.nanoTime() - t0) / 1_000_000;
        assertEquals("SUCCESS", r1.path("result").path("result").asText());
        assertTrue("the move took " + ms1 + " ms, the world says 500", ms1 >= 450);
        assertNotNull("the battery after the move", awaitBattery(40));
        assertNotNull("the arrival event", probe.await("roqme.context",
                b -> b.path("name").asText().equals("Arrived") && b.path("type").asText().equals("event"), TIMEOUT));

        // half the speed: the way back takes 20 s of world time and 20 % of battery
        query("{\"id\":2,\"msg-type\":\"query\",\"query\":{\"type\":\"change-parameter\",\"ParameterSetRepository\":"
                + "\"CommNavigationObjects\",\"ParameterSet\":\"CdParameter\",\"Component\":\"SmartCdServer\","
                + "\"Parameter\":\"transvel\",\"values\":{\"1\":50,\"2\":50}}}");
        long t1 = System.nanoTime();
        JsonNode r2 = push(3, "{\"x\": 0, \"y\": 0}");
        long ms2 = (System.nanoTime() - t1) / 1_000_000;
        assertEquals("SUCCESS", r2.path("result").path("result").asText());
        assertTrue("the slower move took " + ms2 + " ms, the world says 1000", ms2 >= 950);
        assertNotNull("the battery after the slower move", awaitBattery(20));
        assertTrue("no battery reading below what the moves drained",
                probe.messages("roqme.context").stream().filter(m -> m.body().path("name").asText().equals("Battery"))
                        .allMatch(m -> m.body().path("value").asDouble() > 20 - 1e-6));
    }

    @Test
    public void anAbortedMoveStopsDrainingAndNeverArrives() throws Exception {
        assertNotNull(probe.await("roqme.context", b -> b.path("name").asText().equals("Battery"), TIMEOUT));
        awaitSubscriberConnected();
        query("{\"id\":5,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"MoveTo\",\"in-attribute\":{\"x\": 10, \"y\": 0}}}");
        query("{\"id\":6,\"msg-type\":\"query\",\"query\":{\"type\":\"abort-current-skill\"}}");
        assertEquals("ABORT", result(5).path("result").path("result").asText());
        // from the abort on the battery holds: two readings published after it are the same, above what a whole move leaves
        long aborted = System.currentTimeMillis();
        double[] after = batteryAfter(aborted, 2);
        assertEquals(after[0], after[1], 1e-9);
        assertTrue("drained " + (50 - after[0]) + " % before the abort", after[0] > 40);
        assertTrue(probe.messages("roqme.context").stream().noneMatch(m -> m.body().path("name").asText().equals("Arrived")));
    }

    // Demo waits for this: the world's clock starts with the first skill pushed, so a robot slow to
    // start does not sit charging at the dock meanwhile.
    @Test
    public void withoutBeginTheClockStartsWithTheFirstPush() throws Exception {
        LiveWorld world = new LiveWorld(WorldReader.read(WORLD, "test.world.json", ENV), 1, SCALE, Map.of(), ep.busIn());
        List<String> finished = new java.util.concurrent.CopyOnWriteArrayList<>();
        world.start((id, result, value, outputs) -> finished.add(id + " " + result), System.currentTimeMillis());
        world.advance(System.currentTimeMillis());
        assertFalse("no clock before a push", world.awaitStarted(100));
        world.push(7, Json.MAPPER.readTree("{\"name\":\"MoveTo\",\"in-attribute\":{\"x\": 10, \"y\": 0}}"),
                System.currentTimeMillis());
        try {
            assertTrue(world.awaitStarted(0));
        } finally {
            world.close();
        }
    }

    /** The first {@code n} Battery readings the world published after wall time {@code t} (their own "time"). */
    private double[] batteryAfter(long t, int n) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (System.currentTimeMillis() < end) {
            double[] found = probe.messages("roqme.context").stream()
                    .filter(m -> m.body().path("name").asText().equals("Battery") && m.body().path("time").asLong() > t)
                    .mapToDouble(m -> m.body().path("value").asDouble()).limit(n).toArray();
            if (found.length == n) {
                return found;
            }
            Thread.sleep(20);
        }
        throw new AssertionError("fewer than " + n + " Battery readings after " + t);
    }

    private JsonNode awaitBattery(double value) throws InterruptedException {
        return probe.await("roqme.context", b -> b.path("name").asText().equals("Battery")
                && Math.abs(b.path("value").asDouble() - value) < 1e-6, TIMEOUT);
    }

    /** Pushes a move and waits for its result. */
    private JsonNode push(long id, String in) throws Exception {
        query("{\"id\":" + id + ",\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"MoveTo\",\"in-attribute\":" + in + "}}");
        return result(id);
    }

    /** The result of skill {@code id} (the probes' results skipped). */
    private JsonNode result(long id) throws Exception {
        results.setReceiveTimeOut((int) TIMEOUT);
        while (true) {
            String r = results.recvStr();
            assertNotNull("a result for skill " + id, r);
            JsonNode msg = Json.MAPPER.readTree(r);
            if (msg.path("id").asLong() == id) {
                return msg;
            }
        }
    }

    private void query(String json) {
        req.send(json);
        byte[] ack = req.recv();
        assertNotNull("ack", ack);
        assertArrayEquals(new byte[0], ack);
    }

    /** Pushes instant skills until one result arrives, so later results are not lost to the slow joiner. */
    private void awaitSubscriberConnected() throws Exception {
        results.setReceiveTimeOut(300);
        for (int i = 0; i < 100; i++) {
            query("{\"id\":-1,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"Ping\"}}");
            if (results.recvStr() != null) {
                return;
            }
        }
        throw new AssertionError("skill result subscriber never connected");
    }
}
