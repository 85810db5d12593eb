package org.miron.runtime.broker;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.Bus;
import org.miron.runtime.bus.BusClient;
import org.miron.testkit.runtime.BusProbe;

/**
 * The broker's local links against the same broker's sockets: what a local component publishes
 * reaches external subscribers as if it came over the XSUB (bodies, per-topic order, the cache),
 * what anybody publishes reaches local subscribers in the one order the broker forwards in, and a
 * local subscriber's bugs and slowness stay its own.
 */
public class LocalBusTest {
    private static final long TIMEOUT = 10_000;
    private final Endpoints ep = Endpoints.freeLoopback();
    private Broker broker;
    private final List<AutoCloseable> open = new ArrayList<>();

    @Before
    public void setUp() {
        broker = new Broker(ep).start();
    }

    @After
    public void tearDown() throws Exception {
        Collections.reverse(open);
        for (AutoCloseable c : open) {
            c.close();
        }
        broker.close();
    }

    private <T extends AutoCloseable> T keep(T c) {
        open.add(c);
        return c;
    }

    /** A local link that records "topic body" of every message, and "sync" where the replay ended. */
    private Bus local(String name, List<String> seen, String... prefixes) throws InterruptedException {
        Bus b = keep(broker.local().open(name, List.of(prefixes), (t, body) -> {
            synchronized (seen) {
                seen.add(t + " " + new String(body, StandardCharsets.UTF_8));
                seen.notifyAll();
            }
        }));
        b.onBrokerSync((epoch, first) -> {
            synchronized (seen) {
                seen.add("sync " + first);
                seen.notifyAll();
            }
        }).start();
        assertTrue(b.awaitReady(TIMEOUT));
        return b;
    }

    private static List<String> await(List<String> seen, int n) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        synchronized (seen) {
            while (seen.size() < n && System.currentTimeMillis() < end) {
                seen.wait(100);
            }
            return new ArrayList<>(seen);
        }
    }

    private static String estimate(String name, int seq) {
        return "{\"name\":\"" + name + "\",\"namespace\":\"N\",\"value\":0.5,\"seq\":" + seq + "}";
    }

    @Test
    public void localOutputReachesExternalSubscribersAndTheCacheAsFromASocket() throws Exception {
        Bus engine = local("engine", new ArrayList<>());
        try (BusProbe probe = new BusProbe(ep.busOut(), "miron.")) {
            // an external subscriber's subscription is live once it sees the broker's hello
            assertNotNull(probe.await("miron.broker.hello", b -> true, TIMEOUT));
            for (int i = 0; i < 200; i++) {
                engine.publish("miron.variant." + (i % 2 == 0 ? "task" : "mode"), "{\"seq\":" + i + "}");
            }
            assertTrue(engine.flush(TIMEOUT));
            assertNotNull(probe.await("miron.variant.mode", b -> b.path("seq").asInt() == 199, TIMEOUT));
            for (String vp : List.of("task", "mode")) {
                List<Integer> seqs = probe.messages("miron.variant." + vp).stream().map(m -> m.body().path("seq").asInt()).toList();
                assertEquals(vp + ": every message, in order", 100, seqs.size());
                for (int k = 0; k < seqs.size(); k++) {
                    assertEquals(vp.equals("task") ? 2 * k : 2 * k + 1, (int) seqs.get(k));
                }
            }
        }
        try (BusProbe late = new BusProbe(ep.busOut(), "miron.variant.")) {
            assertEquals("the cache holds the local link's last value", 198,
                    late.await("miron.variant.task", b -> true, TIMEOUT).path("seq").asInt());
        }
    }

    @Test
    public void everySubscriberSeesTheBrokersOneOrder() throws Exception {
        List<String> mine = new ArrayList<>();
        local("monitors", mine, "roqme.");
        Bus provider = local("provider", new ArrayList<>());
        try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.", "miron.broker.");
                BusClient robot = new BusClient("robot", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
            assertTrue(robot.awaitReady(TIMEOUT));
            assertNotNull(probe.await("miron.broker.hello", b -> true, TIMEOUT)); // its subscription is live
            provider.publish("roqme.context", "{\"marker\":true}");
            assertNotNull(probe.await("roqme.context", b -> b.path("marker").asBoolean(), TIMEOUT));
            int base = await(mine, 2).size();
            Thread external = new Thread(() -> {
                for (int i = 0; i < 300; i++) {
                    robot.publish("roqme.context", "{\"from\":\"robot\",\"seq\":" + i + "}");
                }
            });
            external.start();
            for (int i = 0; i < 300; i++) {
                provider.publish("roqme.context", "{\"from\":\"provider\",\"seq\":" + i + "}");
            }
            external.join();
            List<String> local = await(mine, base + 600).subList(base, base + 600).stream()
                    .map(s -> s.substring("roqme.context ".length())).toList();
            List<String> external2 = List.of();
            for (long end = System.currentTimeMillis() + TIMEOUT; external2.size() < 600 && System.currentTimeMillis() < end;) {
                Thread.sleep(20);
                external2 = probe.messages("roqme.context").stream().filter(m -> m.body().has("from"))
                        .map(m -> m.body().toString()).toList();
            }
            assertEquals("the external and the local subscriber saw one interleaving", local, external2);
            assertTrue("both publishers interleaved",
                    local.stream().map(s -> s.contains("robot")).collect(Collectors.toSet()).size() == 2);
        }
    }

    @Test
    public void aLateLocalSubscriberGetsTheLatestOfEachSubjectOnceThenItsSync() throws Exception {
        Bus provider = local("provider", new ArrayList<>());
        for (int seq = 0; seq < 3; seq++) {
            for (String p : List.of("safety", "power_autonomy", "mission")) {
                provider.publish("roqme.estimate", estimate(p, seq));
            }
        }
        provider.publish("miron.status", "{\"state\":\"ok\"}");
        assertTrue(provider.flush(TIMEOUT));
        List<String> seen = new ArrayList<>();
        local("engine", seen, "roqme.");
        assertEquals(List.of("roqme.estimate " + estimate("safety", 2), "roqme.estimate " + estimate("power_autonomy", 2),
                "roqme.estimate " + estimate("mission", 2), "sync true"), await(seen, 4));
        provider.publish("roqme.estimate", estimate("safety", 3));
        assertEquals("then live messages, once", "roqme.estimate " + estimate("safety", 3), await(seen, 5).get(4));
        Thread.sleep(200);
        assertEquals(5, await(seen, 6).size());
    }

    @Test
    public void aFailingOrStuckHandlerHoldsNobodyElse() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        List<String> failing = new ArrayList<>();
        keep(broker.local().open("buggy", List.of("roqme."), (t, b) -> {
            synchronized (failing) {
                failing.add(new String(b, StandardCharsets.UTF_8));
            }
            throw new IllegalStateException("a bug in one component");
        })).start();
        keep(broker.local().open("stuck", List.of("roqme."), (t, b) -> {
            try {
                release.await(TIMEOUT, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        })).start();
        List<String> healthy = new ArrayList<>();
        local("healthy", healthy, "roqme.");
        Bus provider = local("provider", new ArrayList<>());
        try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.", "miron.broker.")) {
            assertNotNull(probe.await("miron.broker.hello", b -> true, TIMEOUT));
            for (int i = 0; i < 50; i++) {
                provider.publish("roqme.estimate", estimate("safety", i));
            }
            List<String> got = await(healthy, 51);
            assertEquals("the healthy subscriber got all 50 while another is stuck: " + got, 51, got.size());
            assertNotNull(probe.await("roqme.estimate", b -> b.path("seq").asInt() == 49, TIMEOUT));
            int n = 0;
            for (long end = System.currentTimeMillis() + TIMEOUT; n < 50 && System.currentTimeMillis() < end; Thread.sleep(10)) {
                synchronized (failing) {
                    n = failing.size();
                }
            }
            assertEquals("a handler that throws still gets every message", 50, n);
        } finally {
            release.countDown();
        }
    }

    /**
     * A quick handler runs on the broker's thread; what it publishes while handling a message goes
     * out after that message, to every subscriber (local, quick or not, and external) in one order.
     */
    @Test
    public void whatAQuickHandlerPublishesFollowsTheMessageItHandlesForEverybody() throws Exception {
        Bus[] echo = new Bus[1];
        List<String> quickSaw = Collections.synchronizedList(new ArrayList<>());
        echo[0] = keep(broker.local().open("quick", List.of("roqme.estimate"), (Bus.QuickHandler) (t, b) -> {
            quickSaw.add(Thread.currentThread().getName());
            String body = new String(b, StandardCharsets.UTF_8);
            echo[0].publish("miron.variant.task", "{\"answer\":" + body + "}");
        })).start();
        assertTrue(echo[0].awaitReady(TIMEOUT));
        List<String> seen = new ArrayList<>();
        local("watcher", seen, "roqme.estimate", "miron.variant.");
        int base = await(seen, 1).size();
        try (BusProbe probe = new BusProbe(ep.busOut(), "roqme.estimate", "miron.variant.", "miron.broker.");
                BusClient robot = new BusClient("robot", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
            assertNotNull(probe.await("miron.broker.hello", b -> true, TIMEOUT));
            assertTrue(robot.awaitReady(TIMEOUT));
            for (int i = 0; i < 20; i++) {
                robot.publish("roqme.estimate", estimate("safety", i));
            }
            List<String> local = await(seen, base + 40).subList(base, base + 40);
            for (int i = 0; i < 20; i++) {
                assertEquals("roqme.estimate " + estimate("safety", i), local.get(2 * i));
                assertEquals("miron.variant.task {\"answer\":" + estimate("safety", i) + "}", local.get(2 * i + 1));
            }
            assertNotNull(probe.await("miron.variant.task", b -> b.path("answer").path("seq").asInt() == 19, TIMEOUT));
            List<String> external = probe.messages().stream().filter(m -> !m.topic().startsWith("miron.broker"))
                    .map(m -> m.topic() + " " + m.body()).toList();
            assertEquals("the external subscriber saw the same order", local, external);
            assertTrue("on the broker's thread: " + quickSaw, quickSaw.stream().allMatch(n -> n.equals("broker-bus")));
        }
    }

    @Test
    public void closingFlushesTheLastOutputAndDetaches() throws Exception {
        List<String> seen = new ArrayList<>();
        Bus watcher = local("watcher", seen, "miron.");
        int base = await(seen, 2).size(); // the hello, the sync
        Bus engine = broker.local().open("engine", List.of(), (t, b) -> { }).start();
        assertTrue(engine.awaitReady(TIMEOUT));
        engine.publish("miron.decision", "{\"seq\":1}");
        engine.close(); // at once: the message still leaves
        assertEquals("miron.decision {\"seq\":1}", await(seen, base + 1).get(base));
        watcher.close();
        open.remove(watcher);
        Bus other = local("other", new ArrayList<>());
        other.publish("miron.decision", "{\"seq\":2}");
        assertTrue(other.flush(TIMEOUT));
        Thread.sleep(200);
        assertEquals("a closed link gets nothing more", base + 1, seen.size());
    }

    @Test
    public void anInvalidLocalMessageIsForwardedButNotCachedAndCounted() throws Exception {
        Bus engine = local("engine", new ArrayList<>());
        engine.publish("miron.decision", "{\"seq\":1}");
        engine.publish("miron.decision", "{\"seq\":2"); // looks like JSON, is not: never cached
        assertTrue(engine.flush(TIMEOUT));
        long end = System.currentTimeMillis() + TIMEOUT;
        while (broker.refusedByCache() == 0 && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertEquals(1, broker.refusedByCache());
        try (BusProbe late = new BusProbe(ep.busOut(), "miron.decision")) {
            assertEquals("the last valid value stays cached", 1, late.await("miron.decision", b -> true, TIMEOUT).path("seq").asInt());
        }
    }
}
