package org.miron.runtime;

import java.util.concurrent.atomic.AtomicLong;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * Whether a connecting socket's link is up (ZMTP handshake done), from a ZeroMQ socket monitor.
 * Used where a timer must not include the connection set-up (a request's ack timeout should
 * measure the far side, not a connection still being made or a stalled handshake being retried,
 * see {@link Connect}), and where the loss of an established link matters (skill results cannot
 * arrive over a dropped link). A disconnection counts only after a handshake: a stalled
 * handshake disconnects too. Owned by the thread that owns the socket.
 */
public final class LinkMonitor implements AutoCloseable {
    private static final AtomicLong IDS = new AtomicLong();
    private final ZMQ.Socket socket;
    private final ZMQ.Socket events;
    private boolean up;
    private boolean dropped;

    /** Call before connecting {@code socket}, so the first handshake is not missed. */
    public LinkMonitor(ZContext ctx, ZMQ.Socket socket) {
        String address = "inproc://miron-link-monitor-" + IDS.incrementAndGet();
        this.socket = socket;
        socket.monitor(address, ZMQ.EVENT_HANDSHAKE_PROTOCOL | ZMQ.EVENT_DISCONNECTED);
        events = ctx.createSocket(SocketType.PAIR);
        events.setLinger(0);
        events.connect(address);
    }

    /** Waits up to {@code timeoutMs} for the link to be up; true if it is. */
    public boolean awaitUp(long timeoutMs) {
        long end = System.nanoTime() + timeoutMs * 1_000_000L;
        drain(ZMQ.DONTWAIT);
        long left;
        while (!up && (left = (end - System.nanoTime()) / 1_000_000L) > 0) {
            events.setReceiveTimeOut((int) Math.min(left, 50));
            drain(0);
        }
        return up;
    }

    /** Whether the link is up now (never blocks). */
    public boolean isUp() {
        drain(ZMQ.DONTWAIT);
        return up;
    }

    /** Whether an established link was lost since the last call (never blocks). */
    public boolean dropped() {
        drain(ZMQ.DONTWAIT);
        boolean d = dropped;
        dropped = false;
        return d;
    }

    /** Reads the pending events; with flags 0 the first read waits up to the receive timeout. */
    private void drain(int flags) {
        ZMQ.Event e = ZMQ.Event.recv(events, flags);
        while (e != null) {
            if (e.getEvent() == ZMQ.EVENT_HANDSHAKE_PROTOCOL) {
                up = true;
            } else if (e.getEvent() == ZMQ.EVENT_DISCONNECTED && up) {
                up = false;
                dropped = true;
            }
            e = ZMQ.Event.recv(events, ZMQ.DONTWAIT);
        }
    }

    @Override
    public void close() {
        try {
            socket.monitor(null, 0);
        } catch (RuntimeException e) {
            // the socket is already closed: nothing to stop
        }
        events.close();
    }
}
