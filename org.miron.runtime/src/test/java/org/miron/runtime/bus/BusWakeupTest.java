package org.miron.runtime.bus;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.After;
import org.junit.Test;
import org.miron.runtime.Endpoints;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * The bus thread never waits out its poll: with a one-minute poll interval a publish still leaves
 * and an input still arrives well within the deadline. Times nothing; without the wake-up the
 * publish would sit in the queue for the whole minute and the test would fail.
 */
public class BusWakeupTest {
    private static final long POLL_MS = 60_000;
    private static final int DEADLINE_MS = 10_000;
    private final Endpoints ep = Endpoints.freeLoopback();
    private final ZContext ctx = new ZContext();
    private BusClient client;

    @After
    public void tearDown() {
        if (client != null) {
            client.close();
        }
        ctx.close();
    }

    @Test
    public void publishLeavesWithoutWaitingForThePoll() throws Exception {
        ZMQ.Socket brokerIn = ctx.createSocket(SocketType.XSUB); // stands in for the broker's XSUB
        brokerIn.bind(ep.busIn());
        brokerIn.setReceiveTimeOut(DEADLINE_MS);
        brokerIn.send(new byte[] { 1 }); // subscribe to everything, as the broker does
        client = new BusClient("wake", ep.busIn(), null, List.of(), (t, b) -> { }).pollInterval(POLL_MS).start();
        long end = System.currentTimeMillis() + DEADLINE_MS;
        while (!client.awaitReady(20) && System.currentTimeMillis() < end) {
            brokerIn.recv(ZMQ.DONTWAIT); // lets the XSUB handle the new connection and send its subscription
        }
        assertTrue(client.awaitReady(0));
        Thread.sleep(200); // the bus thread is back in its one-minute poll
        client.publish("miron.variant.task", "{\"value\":\"dock\"}");
        assertEquals("miron.variant.task", brokerIn.recvStr());
        assertEquals("{\"value\":\"dock\"}", brokerIn.recvStr());
        Thread.sleep(200);
        client.publish("miron.variant.task", "{\"value\":\"pick\"}"); // and again: the wake-up re-arms
        assertEquals("miron.variant.task", brokerIn.recvStr());
        assertEquals("{\"value\":\"pick\"}", brokerIn.recvStr());
    }

    @Test
    public void inputReachesTheHandlerWithoutWaitingForThePoll() throws Exception {
        ZMQ.Socket brokerOut = ctx.createSocket(SocketType.XPUB); // stands in for the broker's XPUB
        brokerOut.bind(ep.busOut());
        brokerOut.setReceiveTimeOut(DEADLINE_MS);
        BlockingQueue<String> received = new ArrayBlockingQueue<>(10);
        client = new BusClient("wake", ep.busIn(), ep.busOut(), List.of("roqme."),
                (t, b) -> received.add(t + " " + new String(b, StandardCharsets.UTF_8))).pollInterval(POLL_MS).start();
        byte[] sub = brokerOut.recv(); // the client's subscription
        assertNotNull(sub);
        assertArrayEquals("roqme.".getBytes(StandardCharsets.UTF_8), java.util.Arrays.copyOfRange(sub, 1, sub.length));
        Thread.sleep(200);
        brokerOut.sendMore("roqme.estimate");
        brokerOut.send("{\"value\":0.2}");
        assertEquals("roqme.estimate {\"value\":0.2}", received.poll(DEADLINE_MS, TimeUnit.MILLISECONDS));
    }
}
