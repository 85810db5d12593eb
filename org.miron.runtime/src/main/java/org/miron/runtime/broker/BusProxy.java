package org.miron.runtime.broker;

import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.Bind;
import org.miron.runtime.SocketWait;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.bus.Wakeup;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;
import org.zeromq.ZFrame;

/**
 * XSUB/XPUB forwarder with a last-value cache.
 *
 * <p>Design: the XSUB side subscribes to everything (so the cache sees every topic, whatever the
 * subscribers want) and downstream subscriptions are not forwarded upstream. The XPUB side runs
 * with {@code XPUB_VERBOSE} so every subscribe message arrives here, even a repeated prefix. On a
 * subscription to prefix P the cached last message of every topic starting with P is re-sent on
 * the XPUB. ZeroMQ has already registered the new subscription when we read it, so the late
 * joiner gets the replay. JeroMQ 0.6 has neither {@code XPUB_MANUAL_LAST_VALUE} nor welcome
 * messages, and XPUB always delivers to every matching pipe, so subscribers that already hold P
 * receive an identical copy of the current value (same body, same {@code seq}): bus messages are
 * state, so that repeat is harmless and receivers may drop it by {@code seq}.
 *
 * <p>Restarts and replay barrier: every broker run has an epoch (random id) and caches a
 * {@code miron.broker.hello {"epoch"}} message, so a subscriber of {@code miron.broker.} gets it
 * on every (re)connection and sees a new epoch after a broker restart. A subscription to
 * {@code miron.broker.sync.<id>} is answered, after its own (empty) replay, by one message on that
 * topic: subscriptions of one connection are handled in order, so a client that subscribes to a
 * fresh sync topic once connected knows, when the answer arrives, that the replay of all its
 * earlier prefixes has been delivered before it.
 *
 * <p>Local links ({@link LocalBus}): components in the broker's process hand their messages to
 * this thread through a queue and a {@link Wakeup}, and are handed theirs by it. A local message
 * is cached and sent on the XPUB like one read from the XSUB, and every message, from either side,
 * goes to the local subscribers at the point it goes to the XPUB: one order for everybody. A local
 * subscriber gets the cache replay once, at attach, in update order, then its sync.
 */
final class BusProxy implements Runnable {
    private static final Logger LOG = Logger.getLogger(BusProxy.class.getName());
    private final ZContext ctx;
    private final String inEndpoint;
    private final String outEndpoint;
    private final LastValueCache cache;
    // unique per broker run: subscribers tell a restarted broker by it
    private final String epoch = Long.toHexString(System.currentTimeMillis()) + "-"
            + Long.toHexString(new SecureRandom().nextLong() & Long.MAX_VALUE);
    private ZMQ.Socket xsub;
    private ZMQ.Socket xpub;
    private volatile boolean running = true;
    private final AtomicLong refused = new AtomicLong();
    private record LocalPublish(LocalBus from, List<byte[]> frames) {
    }
    private static final int LOCAL_QUEUE_LIMIT = 10_000;
    private final BlockingQueue<LocalPublish> localOut = new ArrayBlockingQueue<>(LOCAL_QUEUE_LIMIT);
    private final Queue<LocalBus> attaching = new ConcurrentLinkedQueue<>();
    private final Queue<LocalBus> detaching = new ConcurrentLinkedQueue<>();
    private final AtomicLong localDropped = new AtomicLong();
    private final Wakeup wakeup = new Wakeup();
    private final List<LocalBus> locals = new ArrayList<>(); // bus thread only

    BusProxy(ZContext ctx, String inEndpoint, String outEndpoint, LastValueCache cache) {
        this.ctx = ctx;
        this.inEndpoint = inEndpoint;
        this.outEndpoint = outEndpoint;
        this.cache = cache;
    }

    /** Binds both sockets; called on the starting thread so bind errors surface to the caller. */
    void bind() {
        xsub = ctx.createSocket(SocketType.XSUB);
        xpub = ctx.createSocket(SocketType.XPUB);
        xsub.setLinger(0);
        xpub.setLinger(0);
        xpub.setXpubVerbose(true);
        Bind.bind(xsub, inEndpoint);
        Bind.bind(xpub, outEndpoint);
        xsub.send(new byte[] {1}); // subscribe to all topics; XSUB repeats it to every new publisher
        cache.put(List.of(Topics.BROKER_HELLO.getBytes(StandardCharsets.UTF_8), epochBody()));
    }

    String epoch() {
        return epoch;
    }

    private byte[] epochBody() {
        return ("{\"epoch\":\"" + epoch + "\",\"time\":" + System.currentTimeMillis() + "}").getBytes(StandardCharsets.UTF_8);
    }

    /** Messages forwarded but not cached because they were invalid. */
    long refused() {
        return refused.get();
    }

    void stop() {
        running = false;
        wakeup.signal();
    }

    /** Any thread: a local link's message, for this thread to cache, forward and deliver. */
    void submit(LocalBus from, List<byte[]> frames) {
        LocalPublish p = new LocalPublish(from, frames);
        while (!localOut.offer(p)) {
            LocalPublish old = localOut.poll(); // only when this thread is stuck: drop the oldest, as BusClient does
            if (old != null) {
                old.from().taken();
                if (localDropped.incrementAndGet() % 1000 == 1) {
                    LOG.warning("bus: local messages not taken, dropping the oldest (" + localDropped.get() + " so far)");
                }
            }
        }
        wakeup.signal();
    }

    /** Any thread: attach a local link (its replay and sync follow on this thread). */
    void attach(LocalBus bus) {
        attaching.add(bus);
        wakeup.signal();
    }

    void detach(LocalBus bus) {
        detaching.add(bus);
        wakeup.signal();
    }

    @Override
    public void run() {
        try (SocketWait poller = new SocketWait().add(xsub).add(xpub).add(wakeup.channel())) {
            while (running && !Thread.currentThread().isInterrupted()) {
                boolean ready = poller.await(50);
                boolean woken = wakeup.clear(); // before reading the queues: a later submit wakes the next poll
                boolean idle = true;
                // The poll only paces the loop; non-blocking reads decide. A wake-up the poller
                // misses then costs at most one poll interval, never a stuck message.
                boolean busy = true;
                while (busy && running) {
                    busy = forward() | subscription() | local();
                    idle &= !busy;
                }
                if (ready && !woken && idle) {
                    poller.idle(); // a wake-up with nothing to do: see SocketWait
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("bus proxy stopped: " + e);
            }
        } finally {
            wakeup.close();
        }
    }

    private boolean forward() {
        ZMsg msg = ZMsg.recvMsg(xsub, false);
        if (msg == null) {
            return false;
        }
        List<byte[]> frames = new ArrayList<>();
        for (ZFrame f : msg) {
            frames.add(f.getData());
        }
        if (!cache.put(frames) && refused.incrementAndGet() % 1000 == 1) {
            // forwarded all the same: subscribers count bad input themselves
            LOG.warning("bus: not caching an invalid message on " + new String(frames.get(0), StandardCharsets.UTF_8)
                    + " (" + refused.get() + " refused so far)");
        }
        send(xpub, frames);
        deliver(frames);
        return true;
    }

    /** Attaches, then forwards what the local links published, then detaches; true if there was any. */
    private boolean local() {
        boolean any = false;
        LocalBus bus;
        while ((bus = attaching.poll()) != null) {
            any = true;
            locals.add(bus);
            for (List<byte[]> frames : cache.matching(bus::wants)) {
                bus.offer(frames.get(0), body(frames));
            }
            bus.replayed(epoch);
        }
        for (int n = 0; n < LOCAL_QUEUE_LIMIT; n++) { // bounded: the sockets get their turn
            LocalPublish p = localOut.poll();
            if (p == null) {
                break;
            }
            any = true;
            p.from().taken();
            if (!cache.put(p.frames()) && refused.incrementAndGet() % 1000 == 1) {
                LOG.warning("bus: not caching an invalid message on " + new String(p.frames().get(0), StandardCharsets.UTF_8)
                        + " from " + p.from() + " (" + refused.get() + " refused so far)");
            }
            send(xpub, p.frames());
            deliver(p.frames());
        }
        while ((bus = detaching.poll()) != null) {
            any = true;
            locals.remove(bus);
        }
        return any;
    }

    /** To every local subscriber of the topic. */
    private void deliver(List<byte[]> frames) {
        byte[] topic = frames.get(0);
        for (LocalBus bus : locals) {
            if (bus.wants(topic)) {
                bus.offer(topic, body(frames));
            }
        }
    }

    private static byte[] body(List<byte[]> frames) {
        return frames.size() > 1 ? frames.get(1) : new byte[0];
    }

    private boolean subscription() {
        byte[] data = xpub.recv(ZMQ.DONTWAIT);
        if (data == null) {
            return false;
        }
        if (data.length == 0 || data[0] != 1) {
            return true; // unsubscribe or garbage: nothing to replay
        }
        byte[] prefix = Arrays.copyOfRange(data, 1, data.length);
        for (List<byte[]> frames : cache.matching(prefix)) {
            send(xpub, frames);
        }
        if (startsWith(prefix, SYNC)) {
            send(xpub, List.of(prefix, epochBody())); // the replay barrier, never cached
        }
        return true;
    }

    private static final byte[] SYNC = Topics.BROKER_SYNC_PREFIX.getBytes(StandardCharsets.UTF_8);

    private static boolean startsWith(byte[] data, byte[] prefix) {
        return data.length > prefix.length && Arrays.equals(data, 0, prefix.length, prefix, 0, prefix.length);
    }

    private static void send(ZMQ.Socket socket, List<byte[]> frames) {
        for (int i = 0; i < frames.size(); i++) {
            socket.send(frames.get(i), i < frames.size() - 1 ? ZMQ.SNDMORE : 0);
        }
    }
}
