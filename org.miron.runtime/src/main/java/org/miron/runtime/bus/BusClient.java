package org.miron.runtime.bus;

import org.miron.runtime.Contexts;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.miron.runtime.Json;
import org.miron.runtime.SocketWait;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * One component's connection to the bus, owned by a single I/O thread (ZeroMQ sockets are not
 * thread-safe): a SUB on the broker's XPUB for inputs and an XPUB connected to the broker's XSUB
 * for outputs. Any thread may {@link #publish}; messages wait in a bounded queue and a
 * {@link Wakeup} makes the bus thread send them at once (the poll timeout only paces the loop).
 *
 * <p>Why an XPUB to publish: a PUB drops whatever it sends before the broker's subscription has
 * arrived (slow joiner), which would lose the engine's very first decision. The XPUB sees the
 * broker's subscribe-all message, so output is held back until the broker is really listening.
 *
 * <p>Broker restarts. The output XPUB keeps a pipe only while connected, so a restarted broker's
 * XSUB shows up as a new subscribe-all message (and a lost one as an unsubscribe, which holds the
 * output in the queue meanwhile). On every subscribe-all after the first, the last message of
 * every {@link #publishRetained retained} key is queued again: the new broker's cache starts
 * empty, and the component re-announces what it owns (the engine its decisions and status, the
 * player its estimates). On the input side, {@link #onBrokerSync} follows the broker's
 * {@code miron.broker.hello} epoch: on each new epoch (first connection or restart) it subscribes
 * to a fresh {@code miron.broker.sync.<id>} topic and reports when the broker answers it, which is
 * after the last-value cache replay of every other subscribed prefix (see BusProxy).
 */
public final class BusClient implements Bus {
    private static final Logger LOG = Logger.getLogger(BusClient.class.getName());
    private static final int QUEUE_LIMIT = 10_000;

    private final String name;
    private final String publishEndpoint;
    private final String subscribeEndpoint;
    private final List<String> subscriptions;
    private final Bus.Handler handler;
    private final ZContext ctx = Contexts.create();
    private final BlockingQueue<String[]> outbox = new ArrayBlockingQueue<>(QUEUE_LIMIT);
    private final CountDownLatch ready = new CountDownLatch(1);
    private final AtomicLong dropped = new AtomicLong();
    private final Thread thread;
    private final Wakeup wakeup = new Wakeup();
    private volatile long pollMs = 10;
    private volatile boolean running = true;
    private volatile boolean sending;
    private final Map<String, String[]> retained = new LinkedHashMap<>(); // guarded by itself
    private Bus.SyncListener syncListener;
    private final String syncId = Long.toHexString(System.nanoTime()) + Integer.toHexString(System.identityHashCode(this));
    private String epoch; // bus thread only
    private String syncTopic; // bus thread only
    private int syncs; // bus thread only
    private boolean syncAnswered; // bus thread only
    private boolean syncedOnce; // bus thread only
    private boolean upstream; // bus thread only: the broker currently subscribes to our output
    private boolean upstreamSeen; // bus thread only

    /**
     * @param publishEndpoint   broker XSUB (bus in)
     * @param subscribeEndpoint broker XPUB (bus out); may be null when nothing is subscribed
     * @param subscriptions     topic prefixes
     */
    public BusClient(String name, String publishEndpoint, String subscribeEndpoint,
            List<String> subscriptions, Bus.Handler handler) {
        this.name = name;
        this.publishEndpoint = publishEndpoint;
        this.subscribeEndpoint = subscribeEndpoint;
        this.subscriptions = List.copyOf(subscriptions);
        this.handler = handler;
        this.thread = new Thread(this::loop, name + "-bus");
        this.thread.setDaemon(true);
    }

    /** Follows the broker's epochs and replay (see the class comment), on the bus thread; call before {@link #start}. */
    @Override
    public BusClient onBrokerSync(Bus.SyncListener listener) {
        this.syncListener = listener;
        return this;
    }

    /**
     * Longest sleep of the bus thread between checks of its sockets (default 10 ms). Nothing waits
     * for it: publishes wake the thread and socket events end the poll; it only bounds the cost of
     * a missed ZeroMQ wake-up. Tests set it high to prove that.
     */
    public BusClient pollInterval(long ms) {
        this.pollMs = ms;
        return this;
    }

    @Override
    public BusClient start() {
        thread.start();
        return this;
    }

    /** Queues a two-frame message; drops the oldest queued one when the broker is unreachable long. */
    @Override
    public void publish(String topic, String body) {
        String[] msg = {topic, body};
        while (!outbox.offer(msg)) {
            if (outbox.poll() != null && dropped.incrementAndGet() % 1000 == 1) {
                LOG.warning(name + ": bus unreachable, dropping oldest queued messages");
            }
        }
        wakeup.signal();
    }

    /**
     * Publishes and remembers the message as the current value of {@code key}; after a broker
     * restart the last message of every key is published again.
     */
    @Override
    public void publishRetained(String key, String topic, String body) {
        synchronized (retained) {
            retained.remove(key); // re-insert: re-announced in update order
            retained.put(key, new String[] {topic, body});
        }
        publish(topic, body);
    }

    /** Waits until the broker has subscribed to our output. */
    @Override
    public boolean awaitReady(long timeoutMs) throws InterruptedException {
        return ready.await(timeoutMs, TimeUnit.MILLISECONDS);
    }

    /** Waits until every queued message has been handed to ZeroMQ. */
    @Override
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
        // A pipe only while connected (JeroMQ 0.6.0's flag is inverted, see RequestProxy): a broker
        // that goes away unsubscribes, a restarted one subscribes again and is noticed.
        out.setImmediate(false);
        Connect.connect(out, publishEndpoint);
        ZMQ.Socket in = null;
        if (subscribeEndpoint != null && !subscriptions.isEmpty()) {
            in = ctx.createSocket(SocketType.SUB);
            in.setLinger(0);
            Connect.connect(in, subscribeEndpoint);
            for (String s : subscriptions) {
                in.subscribe(s.getBytes(StandardCharsets.UTF_8));
            }
            if (syncListener != null) {
                in.subscribe(Topics.BROKER_PREFIX.getBytes(StandardCharsets.UTF_8));
            }
        }
        try (SocketWait poller = new SocketWait()) {
            poller.add(out);
            if (in != null) {
                poller.add(in);
            }
            poller.add(wakeup.channel());
            while (running) {
                boolean ready = poller.await(pollMs);
                boolean woken = wakeup.clear(); // before reading the queue: a later publish wakes the next poll
                // The poll only paces the loop; non-blocking reads decide (robust to missed wake-ups).
                // Round again after any work: a send or subscribe may consume the notification of
                // a message that then sits in a socket whose FD is no longer readable; the FD
                // only signals again once a read has found the socket empty (see SocketWait).
                int work = 0;
                int round;
                do {
                    round = 0;
                    byte[] sub;
                    while ((sub = out.recv(ZMQ.DONTWAIT)) != null) {
                        upstream(sub);
                        round++;
                    }
                    if (in != null) {
                        round += receive(in);
                    }
                    if (upstream) {
                        round += drain(out);
                    }
                    work += round;
                } while (round > 0 && running);
                if (ready && !woken && work == 0) {
                    poller.idle(); // a wake-up with nothing to do: see SocketWait
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe(name + ": bus connection failed: " + e);
            }
        } finally {
            ctx.close();
            wakeup.close();
        }
    }

    /** The broker's XSUB subscribing (1) or going away (0). */
    private void upstream(byte[] sub) {
        if (sub.length == 0 || sub[0] > 1) {
            return;
        }
        if (sub[0] == 0) {
            upstream = false; // hold output in the queue until a broker listens again
            return;
        }
        upstream = true;
        ready.countDown();
        if (upstreamSeen) {
            reannounce();
        }
        upstreamSeen = true;
    }

    private void reannounce() {
        synchronized (retained) {
            if (!retained.isEmpty()) {
                LOG.info(name + ": broker (re)connected, re-announcing " + retained.size() + " retained messages");
            }
            for (String[] msg : retained.values()) {
                publish(msg[0], msg[1]);
            }
        }
    }

    /** Broker hello and sync answers; true when the message was one (not for the handler). */
    private boolean brokerMessage(ZMQ.Socket in, String topic, byte[] body) {
        if (syncListener == null || !topic.startsWith(Topics.BROKER_PREFIX)) {
            return false;
        }
        if (topic.equals(Topics.BROKER_HELLO)) {
            String e = epochOf(body);
            if (e != null && !e.equals(epoch)) {
                epoch = e;
                if (syncTopic != null) {
                    in.unsubscribe(syncTopic.getBytes(StandardCharsets.UTF_8));
                }
                // subscribed now, on the live connection: handled after every earlier subscription
                syncTopic = Topics.BROKER_SYNC_PREFIX + syncId + "." + (++syncs);
                syncAnswered = false;
                in.subscribe(syncTopic.getBytes(StandardCharsets.UTF_8));
            }
        } else if (topic.equals(syncTopic) && !syncAnswered && epoch.equals(epochOf(body))) {
            syncAnswered = true; // a reconnection re-sends our subscriptions: report once per epoch
            boolean first = !syncedOnce;
            syncedOnce = true;
            try {
                syncListener.synced(epoch, first);
            } catch (RuntimeException e) {
                LOG.warning(name + ": sync listener failed: " + e);
            }
        }
        return subscriptions.stream().noneMatch(topic::startsWith);
    }

    private static String epochOf(byte[] body) {
        try {
            return Json.MAPPER.readTree(body).path("epoch").asText(null);
        } catch (java.io.IOException | RuntimeException e) {
            return null;
        }
    }

    /** Hands every waiting message to the handler; returns how many there were. */
    private int receive(ZMQ.Socket in) {
        int n = 0;
        byte[] topic = in.recv(ZMQ.DONTWAIT);
        while (topic != null) {
            n++;
            byte[] body = in.hasReceiveMore() ? in.recv() : new byte[0];
            while (in.hasReceiveMore()) {
                in.recv(); // extra frames are not part of the protocol
            }
            try {
                String t = new String(topic, StandardCharsets.UTF_8);
                if (!brokerMessage(in, t, body)) {
                    handler.onMessage(t, body);
                }
            } catch (RuntimeException e) {
                LOG.warning(name + ": handler failed on " + new String(topic, StandardCharsets.UTF_8) + ": " + e);
            }
            topic = in.recv(ZMQ.DONTWAIT);
        }
        return n;
    }

    /** Sends the queued messages; returns how many. */
    private int drain(ZMQ.Socket out) {
        int n = 0;
        String[] msg;
        sending = true;
        try {
            while ((msg = outbox.poll()) != null) {
                out.sendMore(msg[0]);
                out.send(msg[1]);
                n++;
            }
        } finally {
            sending = false;
        }
        return n;
    }

    @Override
    public void close() {
        running = false;
        wakeup.signal();
        try {
            thread.join(3000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
