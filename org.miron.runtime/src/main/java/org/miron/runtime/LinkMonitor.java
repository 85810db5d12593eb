package org.miron.runtime;

import java.util.concurrent.atomic.AtomicLong;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/**
 * Whether a connecting socket's link is up (ZMTP handshake done), from a ZeroMQ socket monitor.
 * Used where a timer must not include the connection set-up: a request's ack timeout should
 * measure the far side, not a connection still being made (or a stalled handshake being retried,
 * see {@link Connect}). Owned by the thread that owns the socket.
 */
public final class LinkMonitor implements AutoCloseable {
    private static final AtomicLong IDS = new AtomicLong();
    private final ZMQ.Socket socket;
    private final ZMQ.Socket events;
    private boolean up;

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
        while (true) {
            ZMQ.Event e;
            while ((e = ZMQ.Event.recv(events, ZMQ.DONTWAIT)) != null) {
                if (e.getEvent() == ZMQ.EVENT_HANDSHAKE_PROTOCOL) {
                    up = true;
                } else if (e.getEvent() == ZMQ.EVENT_DISCONNECTED) {
                    up = false;
                }
            }
            long left = (end - System.nanoTime()) / 1_000_000L;
            if (up || left <= 0) {
                return up;
            }
            events.setReceiveTimeOut((int) Math.min(left, 50));
            ZMQ.Event e2 = ZMQ.Event.recv(events);
            if (e2 != null) {
                up = e2.getEvent() == ZMQ.EVENT_HANDSHAKE_PROTOCOL || (up && e2.getEvent() != ZMQ.EVENT_DISCONNECTED);
            }
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
