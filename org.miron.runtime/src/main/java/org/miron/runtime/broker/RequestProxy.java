package org.miron.runtime.broker;

import java.util.logging.Logger;
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
        backend.connect(backendEndpoint);
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
                if (poller.poll(100) <= 0) {
                    continue;
                }
                if (poller.pollin(0)) {
                    relay(frontend, backend);
                }
                if (poller.pollin(1)) {
                    relay(backend, frontend);
                }
            }
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe("request proxy stopped: " + e);
            }
        }
    }

    private static void relay(ZMQ.Socket from, ZMQ.Socket to) {
        ZMsg msg = ZMsg.recvMsg(from, false);
        if (msg != null) {
            msg.send(to);
        }
    }
}
