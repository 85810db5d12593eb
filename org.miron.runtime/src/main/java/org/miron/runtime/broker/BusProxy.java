package org.miron.runtime.broker;

import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Logger;
import org.miron.runtime.Bind;
import org.miron.runtime.SocketWait;
import org.miron.runtime.bus.Topics;
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
 * <p>Local links ({@link LocalBus}): a component in the broker's process publishes on its own
 * thread, which caches the message and sends it on the XPUB as this thread does a message read
 * from the XSUB, with no hand-over to this thread (each one costs a wake-up, the tail of the
 * loop's latency). Every message, from either side, goes to the local subscribers where it goes to
 * the XPUB. All of that happens under one lock, so there is one order for everybody. The XPUB is
 * a ZeroMQ socket used by several threads this way: only under the lock (which is also the memory
 * barrier ZeroMQ asks for when a socket changes threads), and whoever sent on it last reads its
 * pending subscriptions before letting go, since the send may have taken their wake-up from this
 * thread's poll (see SocketWait). A local subscriber gets the cache replay once, at attach, in
 * update order, then its sync. A quick handler ({@link org.miron.runtime.bus.Bus.QuickHandler}) runs
 * right there, under the lock; what it publishes goes out after the message it was handed, to
 * everybody, so the one order holds.
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
    /** Guards the XPUB, the cache's order and {@link #locals}; held for one message at a time. */
    private final Object lock = new Object();
    private final List<LocalBus> locals = new ArrayList<>(); // under lock
    private boolean open; // under lock: the sockets may be used
    private boolean delivering; // under lock: handing a message to the local subscribers
    private final java.util.ArrayDeque<List<byte[]>> nested = new java.util.ArrayDeque<>(); // under lock

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
        synchronized (lock) {
            open = true;
        }
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
    }

    /** Any thread: a local link's message, cached, forwarded and delivered before this returns. */
    void publish(LocalBus from, List<byte[]> frames) {
        synchronized (lock) {
            if (!open) {
                return; // the broker has stopped: as a socket client's message to a broker that is gone
            }
            if (delivering) {
                nested.add(frames); // a quick handler publishing: after the message it is handling
                return;
            }
            dispatch(frames, from.toString());
            while (subscription()) {
                // ours to answer now: the send may have consumed their wake-up
            }
        }
    }

    /** Any thread: a local link attached, its cache replay and sync queued to it before this returns. */
    void attach(LocalBus bus) {
        synchronized (lock) {
            locals.add(bus);
            delivering = true;
            try {
                for (List<byte[]> frames : cache.matching(bus::wants)) {
                    bus.offer(frames.get(0), body(frames));
                }
                bus.replayed(epoch);
            } finally {
                delivering = false;
            }
            drainNested();
        }
    }

    void detach(LocalBus bus) {
        synchronized (lock) {
            locals.remove(bus);
        }
    }

    @Override
    public void run() {
        try (SocketWait poller = new SocketWait().add(xsub).add(xpub)) {
            while (running && !Thread.currentThread().isInterrupted()) {
                boolean ready = poller.await(50);
                boolean idle = true;
                // The poll only paces the loop; non-blocking reads decide. A wake-up the poller
                // misses then costs at most one poll interval, never a stuck message.
                boolean busy = true;
                while (busy && running) {
                    synchronized (lock) {
                        busy = forward() | subscription();
                    }
                    idle &= !busy;
                }
                if (ready && idle) {
                    poller.idle(); // a wake-up with nothing to do: see SocketWait
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("bus proxy stopped: " + e);
            }
        } finally {
            synchronized (lock) {
                open = false; // the broker closes the sockets next
            }
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
        dispatch(frames, null);
        return true;
    }

    /** One message, then what quick handlers published meanwhile. */
    private void dispatch(List<byte[]> frames, String from) {
        pass(frames, from);
        drainNested();
    }

    private void drainNested() {
        List<byte[]> next;
        while (!delivering && (next = nested.poll()) != null) {
            pass(next, null);
        }
    }

    /** Caches, forwards on the XPUB and delivers to the local subscribers one message. */
    private void pass(List<byte[]> frames, String from) {
        admit(frames, from);
        send(xpub, frames);
        deliver(frames);
    }

    /** Caches a valid message; an invalid one is forwarded all the same (subscribers count bad input themselves). */
    private void admit(List<byte[]> frames, String from) {
        if (!cache.put(frames) && refused.incrementAndGet() % 1000 == 1) {
            LOG.warning("bus: not caching an invalid message on " + new String(frames.get(0), StandardCharsets.UTF_8)
                    + (from == null ? "" : " from " + from) + " (" + refused.get() + " refused so far)");
        }
    }

    /** To every local subscriber of the topic. */
    private void deliver(List<byte[]> frames) {
        byte[] topic = frames.get(0);
        delivering = true;
        try {
            for (LocalBus bus : locals) {
                if (bus.wants(topic)) {
                    bus.offer(topic, body(frames));
                }
            }
        } finally {
            delivering = false;
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
