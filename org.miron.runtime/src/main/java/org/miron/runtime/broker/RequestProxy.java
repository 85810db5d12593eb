package org.miron.runtime.broker;

import java.util.logging.Logger;
import org.miron.runtime.Bind;
import org.miron.runtime.Connect;
import org.miron.runtime.SocketWait;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZFrame;
import org.zeromq.ZMsg;

/**
 * ROUTER/DEALER queue device of the original MIRoN broker: REQ clients talk to the ROUTER, the
 * DEALER connects to the skill interface REP. Envelopes pass through untouched, so the REP's
 * reply finds its way back to the right client. Own loop instead of {@code ZMQ.proxy} so that
 * stop() ends it without tearing the context down under it.
 */
final class RequestProxy implements Runnable {
    private static final Logger LOG = Logger.getLogger(RequestProxy.class.getName());
    private final ZContext ctx;
    private final String frontendEndpoint;
    private final String backendEndpoint;
    private ZMQ.Socket frontend;
    private ZMQ.Socket backend;
    private volatile boolean running = true;

    RequestProxy(ZContext ctx, String frontendEndpoint, String backendEndpoint) {
        this.ctx = ctx;
        this.frontendEndpoint = frontendEndpoint;
        this.backendEndpoint = backendEndpoint;
    }

    void bind() {
        frontend = ctx.createSocket(SocketType.ROUTER);
        backend = ctx.createSocket(SocketType.DEALER);
        frontend.setLinger(0);
        backend.setLinger(0);
        // Queue requests only on a live connection: while the skill interface is down they are
        // dropped (clients time out and retry) instead of piling up and replaying stale values.
        // JeroMQ 0.6.0's flag is inverted with respect to libzmq's ZMQ_IMMEDIATE: false means
        // "no pipe before the connection is up" (checked in ParameterRetryTest).
        backend.setImmediate(false);
        Bind.bind(frontend, frontendEndpoint);
        Connect.connect(backend, backendEndpoint);
    }

    void stop() {
        running = false;
    }

    @Override
    public void run() {
        try (SocketWait poller = new SocketWait().add(frontend).add(backend)) {
            while (running && !Thread.currentThread().isInterrupted()) {
                boolean ready = poller.await(50);
                boolean idle = true;
                // The poll only paces the loop; non-blocking reads decide (robust to missed wake-ups).
                boolean busy = true;
                while (busy && running) {
                    busy = relay(frontend, backend, "skill interface not connected")
                            | relay(backend, frontend, "client gone");
                    idle &= !busy;
                }
                if (ready && idle) {
                    poller.idle(); // a wake-up with nothing to do: see SocketWait
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("request proxy stopped: " + e);
            }
        }
    }

    /** Moves one message; never blocks: a message the other side cannot take now is dropped. */
    private static boolean relay(ZMQ.Socket from, ZMQ.Socket to, String dropReason) {
        ZMsg msg = ZMsg.recvMsg(from, false);
        if (msg == null) {
            return false;
        }
        int n = msg.size();
        int i = 0;
        for (ZFrame f : msg) {
            boolean last = ++i == n;
            if (!to.send(f.getData(), ZMQ.DONTWAIT | (last ? 0 : ZMQ.SNDMORE)) && i == 1) {
                LOG.fine("request dropped: " + dropReason);
                break; // nothing queued yet, so dropping the whole message is clean
            }
        }
        return true;
    }
}
