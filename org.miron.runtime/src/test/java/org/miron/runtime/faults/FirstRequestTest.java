package org.miron.runtime.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.IoModel;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.TestbotRules;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * Issue 10, item 8: the engine's first change-parameter must not be "lost" and retried because
 * its ack timeout also paid for setting up the connection. Reproduced deterministically with a
 * request path whose far end (a ROUTER acknowledging everything, as the broker + skill interface
 * do) starts listening only after the engine's first decision: the request must then be sent
 * once, acknowledged, and never retried.
 */
public class FirstRequestTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private EngineFixture f;
    private Engine engine;
    private final ZContext ctx = new ZContext();
    private volatile boolean acking = true;

    @After
    public void tearDown() {
        acking = false;
        if (engine != null) {
            engine.close();
        }
        f.close();
        ctx.close();
    }

    @Test
    public void theFirstChangeParameterIsSentOnceTheLinkIsUpAndNeverRetried() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        f.startInfrastructure();
        EngineOptions o = f.options(); // ack timeout 500 ms
        o.request = Endpoints.freeLoopback().request();
        engine = new Engine(IoModel.load(f.ioJson), new TestbotRules(), o).start();
        assertTrue("first decision made", f.awaitVariant("task", "pickDeliverCharge") != null);
        // the request path comes up well after the ack timeout
        long end = System.currentTimeMillis() + 1500;
        while (System.currentTimeMillis() < end) {
            Thread.sleep(50);
        }
        AtomicInteger received = new AtomicInteger();
        Thread router = new Thread(() -> ackEverything(o.request, received));
        router.setDaemon(true);
        router.start();
        long deadline = System.currentTimeMillis() + EngineFixture.TIMEOUT;
        while (engine.status().get("paramAcked") == 0 && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        assertEquals("acknowledged", 1, engine.status().get("paramAcked"));
        assertEquals("sent once", 1, engine.status().get("paramSent"));
        assertEquals("never retried", 0, engine.status().get("paramRetries"));
        assertEquals("one request reached the far end", 1, received.get());
    }

    private void ackEverything(String endpoint, AtomicInteger received) {
        ZMQ.Socket router = ctx.createSocket(SocketType.ROUTER);
        router.setLinger(0);
        router.setReceiveTimeOut(50);
        router.bind(endpoint);
        while (acking) {
            ZMsg msg = ZMsg.recvMsg(router);
            if (msg == null) {
                continue;
            }
            received.incrementAndGet();
            ZMsg ack = new ZMsg();
            ack.add(msg.pop()); // identity
            ack.add(new byte[0]); // delimiter
            ack.add(new byte[0]); // the ack
            ack.send(router);
        }
        router.close();
    }
}
