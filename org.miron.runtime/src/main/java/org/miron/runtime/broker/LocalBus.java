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
 * socket, no I/O thread. What it publishes the broker caches and forwards on the publishing
 * thread, exactly as a message from its XSUB, so external subscribers see the same wire; what it
 * subscribes to it gets in the broker's order, after a replay of the last-value cache, on the
 * connection's own delivery thread, so that a slow handler (a DDS write) holds neither the broker
 * nor the other components; a {@link Bus.QuickHandler} is run by the broker where it delivers,
 * with no thread of its own.
 *
 * <p>The broker lives as long as the process, so there is one epoch and nothing to re-announce:
 * {@link #publishRetained} is {@link #publish}.
 */
final class LocalBus implements Bus {
    private static final Logger LOG = Logger.getLogger(LocalBus.class.getName());
    private static final int QUEUE_LIMIT = 10_000;

    /** Something for the delivery thread: a message, or (topic null) the end of the replay. */
    private record Delivery(String topic, byte[] body) {
    }

    private final BusProxy broker;
    private final String name;
    private final List<byte[]> prefixes;
    private final Bus.Handler handler;
    private final BlockingQueue<Delivery> inbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final AtomicLong dropped = new AtomicLong();
    private final CountDownLatch attached = new CountDownLatch(1);
    private final Thread thread; // null for a quick handler
    private volatile Bus.SyncListener syncListener;
    private volatile boolean running = true;

    LocalBus(BusProxy broker, String name, List<String> subscriptions, Bus.Handler handler) {
        this.broker = broker;
        this.name = name;
        this.prefixes = subscriptions.stream().map(s -> s.getBytes(StandardCharsets.UTF_8)).toList();
        this.handler = handler;
        if (handler instanceof Bus.QuickHandler) {
            this.thread = null;
        } else {
            this.thread = new Thread(this::deliver, name + "-bus");
            this.thread.setDaemon(true);
        }
    }

    @Override
    public LocalBus onBrokerSync(Bus.SyncListener listener) {
        this.syncListener = listener;
        return this;
    }

    @Override
    public LocalBus start() {
        if (thread != null) {
            thread.start();
        }
        broker.attach(this);
        return this;
    }

    @Override
    public void publish(String topic, String body) {
        broker.publish(this, List.of(topic.getBytes(StandardCharsets.UTF_8), body.getBytes(StandardCharsets.UTF_8)));
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

    /** Nothing waits: a publish has left when it returns. */
    @Override
    public boolean flush(long timeoutMs) {
        return true;
    }

    // ---- called by the broker, under its lock ----

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
        Delivery d = new Delivery(topic == null ? null : new String(topic, StandardCharsets.UTF_8), body);
        if (thread == null) {
            handle(d);
        } else {
            queue(d);
        }
    }

    /** The replay of the cache is delivered: tell the sync listener after it. */
    void replayed(String epoch) {
        offer(null, epoch.getBytes(StandardCharsets.UTF_8));
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
            handle(d);
        }
    }

    private void handle(Delivery d) {
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

    @Override
    public void close() {
        broker.detach(this);
        running = false;
        if (thread != null) {
            thread.interrupt();
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Override
    public String toString() {
        return name;
    }
}
