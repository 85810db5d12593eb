package org.miron.runtime.broker;

import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
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
        frontend.bind(frontendEndpoint);
        Connect.connect(backend, backendEndpoint);
    }

    void stop() {
        running = false;
    }

    @Override
    public void run() {
        try (ZMQ.Poller poller = ctx.createPoller(2)) {
            poller.register(frontend, ZMQ.Poller.POLLIN);
            poller.register(backend, ZMQ.Poller.POLLIN);
            while (running && !Thread.currentThread().isInterrupted()) {
                poller.poll(50);
                // Drain regardless of the poller's flags: JeroMQ's poller can miss an edge.
                boolean busy = true;
                while (busy && running) {
                    busy = relay(frontend, backend) | relay(backend, frontend);
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("request proxy stopped: " + e);
            }
        }
    }

    private static boolean relay(ZMQ.Socket from, ZMQ.Socket to) {
        ZMsg msg = ZMsg.recvMsg(from, false);
        if (msg == null) {
            return false;
        }
        msg.send(to);
        return true;
    }
}
