package org.miron.runtime.broker;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.bus.Bus;

/**
 * A component's bus connection to a broker in the same process ({@link Broker#local()}): no
 * socket, no I/O thread. What it publishes is handed to the broker's bus thread, which caches
 * and forwards it exactly as a message from its XSUB, so external subscribers see the same wire;
 * what it subscribes to is handed to it by that thread in the broker's order, after a replay of
 * the last-value cache, and run on the connection's own delivery thread so that a slow handler
 * (a DDS write) holds neither the broker nor the other components.
 *
 * <p>The broker lives as long as the process, so there is one epoch and nothing to re-announce:
 * {@link #publishRetained} is {@link #publish}.
 */
final class LocalBus implements Bus {
    private static final Logger LOG = Logger.getLogger(LocalBus.class.getName());
    private static final int QUEUE_LIMIT = 10_000;
    private static final long CLOSE_FLUSH_MS = 1000; // as a socket client's linger: the last outputs leave

    /** Something for the delivery thread: a message, or (topic null) the end of the replay. */
    private record Delivery(String topic, byte[] body) {
    }

    private final BusProxy broker;
    private final String name;
    private final List<byte[]> prefixes;
    private final Bus.Handler handler;
    private final BlockingQueue<Delivery> inbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final AtomicLong unsent = new AtomicLong(); // published, not yet taken by the broker
    private final AtomicLong dropped = new AtomicLong();
    private final CountDownLatch attached = new CountDownLatch(1);
    private final Thread thread;
    private volatile Bus.SyncListener syncListener;
    private volatile boolean running = true;

    LocalBus(BusProxy broker, String name, List<String> subscriptions, Bus.Handler handler) {
        this.broker = broker;
        this.name = name;
        this.prefixes = subscriptions.stream().map(s -> s.getBytes(StandardCharsets.UTF_8)).toList();
        this.handler = handler;
        this.thread = new Thread(this::deliver, name + "-bus");
        this.thread.setDaemon(true);
    }

    @Override
    public LocalBus onBrokerSync(Bus.SyncListener listener) {
        this.syncListener = listener;
        return this;
    }

    @Override
    public LocalBus start() {
        thread.start();
        broker.attach(this);
        return this;
    }

    @Override
    public void publish(String topic, String body) {
        unsent.incrementAndGet();
        broker.submit(this, List.of(topic.getBytes(StandardCharsets.UTF_8), body.getBytes(StandardCharsets.UTF_8)));
    }

    @Override
    public void publishRetained(String key, String topic, String body) {
        publish(topic, body);
    }

    /** Ready once the broker has attached us, i.e. takes our output and replayed its cache to us. */
    @Override
    public boolean awaitReady(long timeoutMs) throws InterruptedException {
        return attached.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    @Override
    public boolean flush(long timeoutMs) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        while (unsent.get() > 0) {
            if (System.nanoTime() > end) {
                return false;
            }
            Thread.sleep(1);
        }
        return true;
    }

    // ---- the broker's bus thread ----

    /** Whether a message on {@code topic} is for us (byte-wise prefix, as ZeroMQ matches). */
    boolean wants(byte[] topic) {
        for (byte[] p : prefixes) {
            if (topic.length >= p.length && java.util.Arrays.equals(topic, 0, p.length, p, 0, p.length)) {
                return true;
            }
        }
        return false;
    }

    /** A message for us; drops our oldest undelivered one when we are far behind (as a ZeroMQ HWM would). */
    void offer(byte[] topic, byte[] body) {
        queue(new Delivery(new String(topic, StandardCharsets.UTF_8), body));
    }

    /** The broker took one of our messages. */
    void taken() {
        unsent.decrementAndGet();
    }

    /** The replay of the cache is delivered: tell the sync listener after it. */
    void replayed(String epoch) {
        queue(new Delivery(null, epoch.getBytes(StandardCharsets.UTF_8)));
        attached.countDown();
    }

    private void queue(Delivery d) {
        while (!inbox.offer(d)) {
            if (inbox.poll() != null && dropped.incrementAndGet() % 1000 == 1) {
                LOG.warning(name + ": behind the bus, dropping its oldest undelivered messages (" + dropped.get() + " so far)");
            }
        }
    }

    // ---- our delivery thread ----

    private void deliver() {
        while (running) {
            Delivery d;
            try {
                d = inbox.take();
            } catch (InterruptedException e) {
                return;
            }
            try {
                if (d.topic() == null) {
                    Bus.SyncListener l = syncListener;
                    if (l != null) {
                        l.synced(new String(d.body(), StandardCharsets.UTF_8), true);
                    }
                } else {
                    handler.onMessage(d.topic(), d.body());
                }
            } catch (RuntimeException e) { // one component's bug stays in it
                LOG.warning(name + ": handler failed on " + d.topic() + ": " + e);
            }
        }
    }

    @Override
    public void close() {
        try {
            flush(CLOSE_FLUSH_MS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        broker.detach(this);
        running = false;
        thread.interrupt();
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public String toString() {
        return name;
    }
}
