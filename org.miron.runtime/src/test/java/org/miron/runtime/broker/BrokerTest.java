package org.miron.runtime.broker;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.runtime.Connect;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.BusClient;
import org.miron.testkit.runtime.BusProbe;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

public class BrokerTest {
    private static final long TIMEOUT = 10_000;
    private final Endpoints ep = Endpoints.freeLoopback();
    private Broker broker;
    private BusClient pub;
    private final ZContext ctx = new ZContext();

    @Before
    public void setUp() throws Exception {
        broker = new Broker(ep).start();
        pub = new BusClient("test", ep.busIn(), null, List.of(), (t, b) -> { }).start();
        assertTrue(pub.awaitReady(TIMEOUT));
    }

    @After
    public void tearDown() {
        pub.close();
        broker.close();
        ctx.close();
    }

    @Test
    public void lateSubscriberGetsLastValueOfEveryMatchingTopic() throws Exception {
        pub.publish("miron.variant.task", "{\"value\":\"pick\",\"seq\":1}");
        pub.publish("miron.variant.task", "{\"value\":\"dock\",\"seq\":2}");
        pub.publish("miron.variant.mode", "{\"value\":\"fast\",\"seq\":2}");
        pub.publish("miron.status", "{\"state\":\"ok\"}");
        assertTrue(pub.flush(TIMEOUT));
        awaitCached(3 + 1); // and the broker's own miron.broker.hello
        try (BusProbe late = new BusProbe(ep.busOut(), "miron.variant.")) {
            JsonNode task = late.await("miron.variant.task", b -> true, TIMEOUT);
            JsonNode mode = late.await("miron.variant.mode", b -> true, TIMEOUT);
            assertNotNull(task);
            assertNotNull(mode);
            assertEquals("only the latest value is replayed", "dock", task.path("value").asText());
            assertEquals(1, late.messages("miron.variant.task").size());
            assertTrue("topics outside the prefix are not replayed", late.messages("miron.status").isEmpty());
        }
    }

    @Test
    public void liveMessagesFlowToSubscribers() throws Exception {
        try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.")) {
            // the probe is ready once it receives anything; publish until then (slow joiner)
            JsonNode got = null;
            for (int i = 0; i < 100 && got == null; i++) {
                pub.publish("roqme.estimate", "{\"value\":" + i + "}");
                got = probe.await("roqme.estimate", b -> true, 100);
            }
            assertNotNull(got);
            pub.publish("roqme.context", "{\"name\":\"x\"}");
            assertNotNull(probe.await("roqme.context", b -> b.path("name").asText().equals("x"), TIMEOUT));
        }
    }

    @Test
    public void requestPathReachesTheSkillInterfaceAndRepliesReturn() throws Exception {
        ZMQ.Socket rep = ctx.createSocket(SocketType.REP);
        rep.setLinger(0);
        rep.bind(ep.skill());
        rep.setReceiveTimeOut(200);
        // Until the broker's DEALER has connected, requests are dropped (never queued): retry.
        ZMQ.Socket probe = ctx.createSocket(SocketType.DEALER);
        probe.setLinger(0);
        Connect.connect(probe, ep.request());
        String got = null;
        for (int i = 0; i < 100 && got == null; i++) {
            probe.sendMore(new byte[0]);
            probe.send("{\"probe\":" + i + "}");
            got = rep.recvStr();
        }
        assertNotNull("request path comes up", got);
        rep.send(new byte[0]);

        ZMQ.Socket req = ctx.createSocket(SocketType.REQ);
        req.setLinger(0);
        req.setReceiveTimeOut((int) TIMEOUT);
        Connect.connect(req, ep.request());
        req.send("{\"id\":1}");
        rep.setReceiveTimeOut((int) TIMEOUT);
        assertEquals("{\"id\":1}", rep.recvStr());
        rep.send(new byte[0]);
        byte[] ack = req.recv();
        assertNotNull("ack returns through ROUTER/DEALER to the right client", ack);
        assertArrayEquals(new byte[0], ack);
    }

    @Test
    public void busyPortIsAClearError() {
        try (Broker second = new Broker(ep)) {
            second.start();
            throw new AssertionError("second broker bound the same ports");
        } catch (IllegalStateException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("cannot bind"));
        }
    }

    @Test
    public void brokenCacheFileIsAClearError() throws Exception {
        java.nio.file.Path file = java.nio.file.Files.createTempFile("miron-cache", ".json");
        try {
            java.nio.file.Files.writeString(file, "[[\"cm9xbWUuZXN0aW1hdGU=\"]] trailing");
            try (Broker other = new Broker(Endpoints.freeLoopback(), file)) {
                other.start();
                throw new AssertionError("broker started on a broken cache file");
            } catch (IllegalStateException e) {
                assertTrue(e.getMessage(), e.getMessage().contains("cannot load its cache file"));
            }
        } finally {
            java.nio.file.Files.deleteIfExists(file);
        }
    }

    private void awaitCached(int topics) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (broker.cachedTopics() < topics && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertEquals(topics, broker.cachedTopics());
    }

    @Test
    public void cacheKeepsTheLatestMessagePerNamedSubject() {
        LastValueCache cache = new LastValueCache(10);
        cache.put(List.of("roqme.estimate".getBytes(), "{\"name\":\"safety\",\"value\":0.1}".getBytes()));
        cache.put(List.of("roqme.estimate".getBytes(), "{\"name\":\"power\",\"value\":0.2}".getBytes()));
        cache.put(List.of("roqme.estimate".getBytes(), "{\"name\":\"safety\",\"value\":0.3}".getBytes()));
        assertFalse("invalid messages are not cached", cache.put(List.of("roqme.estimate".getBytes(), "not json".getBytes())));
        List<List<byte[]>> all = cache.matching("roqme.".getBytes());
        assertEquals(2, all.size());
        assertEquals("{\"name\":\"power\",\"value\":0.2}", new String(all.get(0).get(1)));
        assertEquals("{\"name\":\"safety\",\"value\":0.3}", new String(all.get(1).get(1)));
        assertTrue(cache.matching("roqme.estimateX".getBytes()).isEmpty());
    }

    @Test
    public void cacheIsBounded() {
        LastValueCache cache = new LastValueCache(2);
        cache.put(List.of("a".getBytes(), "1".getBytes()));
        cache.put(List.of("b".getBytes(), "2".getBytes()));
        cache.put(List.of("a".getBytes(), "3".getBytes()));
        cache.put(List.of("c".getBytes(), "4".getBytes()));
        assertEquals(2, cache.size());
        assertTrue("least recently updated topic evicted", cache.matching("b".getBytes()).isEmpty());
        assertEquals("3", new String(cache.matching("a".getBytes()).get(0).get(1)));
    }
}
