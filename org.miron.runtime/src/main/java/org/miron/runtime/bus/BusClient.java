package org.miron.runtime.bus;

import org.miron.runtime.Contexts;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * One component's connection to the bus, owned by a single I/O thread (ZeroMQ sockets are not
 * thread-safe): a SUB on the broker's XPUB for inputs and an XPUB connected to the broker's XSUB
 * for outputs. Any thread may {@link #publish}; messages wait in a bounded queue.
 *
 * <p>Why an XPUB to publish: a PUB drops whatever it sends before the broker's subscription has
 * arrived (slow joiner), which would lose the engine's very first decision. The XPUB sees the
 * broker's subscribe-all message, so output is held back until the broker is really listening.
 */
public final class BusClient implements AutoCloseable {
    /** Receives one bus message: topic and body (the second frame, empty if absent). */
    public interface Handler {
        void onMessage(String topic, byte[] body);
    }

    private static final Logger LOG = Logger.getLogger(BusClient.class.getName());
    private static final int QUEUE_LIMIT = 10_000;

    private final String name;
    private final String publishEndpoint;
    private final String subscribeEndpoint;
    private final List<String> subscriptions;
    private final Handler handler;
    private final ZContext ctx = Contexts.create();
    private final BlockingQueue<String[]> outbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final CountDownLatch ready = new CountDownLatch(1);
    private final AtomicLong dropped = new AtomicLong();
    private final Thread thread;
    private volatile boolean running = true;
    private volatile boolean sending;

    /**
     * @param publishEndpoint   broker XSUB (bus in)
     * @param subscribeEndpoint broker XPUB (bus out); may be null when nothing is subscribed
     * @param subscriptions     topic prefixes
     */
    public BusClient(String name, String publishEndpoint, String subscribeEndpoint,
            List<String> subscriptions, Handler handler) {
        this.name = name;
        this.publishEndpoint = publishEndpoint;
        this.subscribeEndpoint = subscribeEndpoint;
        this.subscriptions = List.copyOf(subscriptions);
        this.handler = handler;
        this.thread = new Thread(this::loop, name + "-bus");
        this.thread.setDaemon(true);
    }

    public BusClient start() {
        thread.start();
        return this;
    }

    /** Queues a two-frame message; drops the oldest queued one when the broker is unreachable long. */
    public void publish(String topic, String body) {
        String[] msg = {topic, body};
        while (!outbox.offer(msg)) {
            if (outbox.poll() != null && dropped.incrementAndGet() % 1000 == 1) {
                LOG.warning(name + ": bus unreachable, dropping oldest queued messages");
            }
        }
    }

    /** Waits until the broker has subscribed to our output. */
    public boolean awaitReady(long timeoutMs) throws InterruptedException {
        return ready.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    /** Waits until every queued message has been handed to ZeroMQ. */
    public boolean flush(long timeoutMs) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (!outbox.isEmpty() || sending) {
            if (System.nanoTime() > end) {
                return false;
            }
            Thread.sleep(5);
        }
        return true;
    }

    private void loop() {
        ZMQ.Socket out = ctx.createSocket(SocketType.XPUB);
        out.setLinger(1000); // let queued output leave on close (the player's last events)
        Connect.connect(out, publishEndpoint);
        ZMQ.Socket in = null;
        if (subscribeEndpoint != null && !subscriptions.isEmpty()) {
            in = ctx.createSocket(SocketType.SUB);
            in.setLinger(0);
            Connect.connect(in, subscribeEndpoint);
            for (String s : subscriptions) {
                in.subscribe(s.getBytes(StandardCharsets.UTF_8));
            }
        }
        try (ZMQ.Poller poller = ctx.createPoller(2)) {
            poller.register(out, ZMQ.Poller.POLLIN);
            if (in != null) {
                poller.register(in, ZMQ.Poller.POLLIN);
            }
            while (running) {
                poller.poll(10);
                // The poll only paces the loop; non-blocking reads decide (robust to missed wake-ups).
                byte[] sub;
                while ((sub = out.recv(ZMQ.DONTWAIT)) != null) {
                    if (sub.length > 0 && sub[0] == 1) {
                        ready.countDown();
                    }
                }
                if (in != null) {
                    receive(in);
                }
                if (ready.getCount() == 0) {
                    drain(out);
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe(name + ": bus connection failed: " + e);
            }
        } finally {
            ctx.close();
        }
    }

    private void receive(ZMQ.Socket in) {
        byte[] topic = in.recv(ZMQ.DONTWAIT);
        while (topic != null) {
            byte[] body = in.hasReceiveMore() ? in.recv() : new byte[0];
            while (in.hasReceiveMore()) {
                in.recv(); // extra frames are not part of the protocol
            }
            try {
                handler.onMessage(new String(topic, StandardCharsets.UTF_8), body);
            } catch (RuntimeException e) {
                LOG.warning(name + ": handler failed on " + new String(topic, StandardCharsets.UTF_8) + ": " + e);
            }
            topic = in.recv(ZMQ.DONTWAIT);
        }
    }

    private void drain(ZMQ.Socket out) {
        String[] msg;
        sending = true;
        try {
            while ((msg = outbox.poll()) != null) {
                out.sendMore(msg[0]);
                out.send(msg[1]);
            }
        } finally {
            sending = false;
        }
    }

    @Override
    public void close() {
        running = false;
        try {
            thread.join(3000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
