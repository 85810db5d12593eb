package org.miron.runtime.skill;

import org.miron.runtime.Contexts;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.miron.runtime.Json;
import org.miron.runtime.SocketWait;
import org.miron.runtime.LinkMonitor;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * Sends requests to the SmartSoft skill interface (through the broker's request path) on its own
 * thread, so a slow or absent skill interface never blocks the caller (the engine's solve loop, the
 * executor's tick). Per key only the latest message is kept (bounded memory: a newer request
 * supersedes a pending one with the same key). Each request waits for the ack (the empty reply
 * frame); without it the socket is dropped (stale replies go with it, "lazy pirate") and the
 * request is retried after an exponential back-off. Used for change-parameter queries (engine) and
 * push-skill / abort-current-skill requests (BT executor).
 *
 * <p>The ack timeout measures the far side only: the socket is connected when the sender starts
 * (and again right after dropping one), and a request is sent only once its link is up
 * ({@link LinkMonitor}). Before, the first request rode a socket created for it, so its 1 s ack
 * timeout also paid for the connection set-up; when JeroMQ's handshake stalled (see
 * {@link Connect}) or the broker was not listening yet, the ack came too late, the socket was
 * dropped with the request and it was retried 1.2 s later (ack timeout + first back-off).
 *
 * <p>The socket is a DEALER speaking REQ's envelope (empty delimiter, then the body), so a lost
 * reply cannot wedge a REQ state machine; the broker's ROUTER sees an ordinary REQ client.
 */
public final class RequestSender implements AutoCloseable {
    /** Progress reports, called on the sender thread. */
    public interface Listener {
        void sent(String key, ObjectNode message);

        void acked(String key, ObjectNode message);

        void retry(String key, ObjectNode message, int attempt, long backoffMs);
    }

    private static final Logger LOG = Logger.getLogger(RequestSender.class.getName());
    private final String endpoint;
    private final long ackTimeoutMs;
    private final long backoffMinMs;
    private final long backoffMaxMs;
    private final Listener listener;
    private final Map<String, ObjectNode> pending = new LinkedHashMap<>();
    private final ZContext ctx = Contexts.create();
    private final Thread thread;
    private volatile boolean running = true;
    public RequestSender(String endpoint, String threadName, long ackTimeoutMs, long backoffMinMs,
            long backoffMaxMs, Listener listener) {
        this.endpoint = endpoint;
        this.ackTimeoutMs = ackTimeoutMs;
        this.backoffMinMs = backoffMinMs;
        this.backoffMaxMs = backoffMaxMs;
        this.listener = listener;
        this.thread = new Thread(this::loop, threadName);
        this.thread.setDaemon(true);
    }

    public RequestSender start() {
        thread.start();
        return this;
    }

    /** Queues a complete message for {@code key}, replacing any not yet acknowledged one with that key. */
    public synchronized void submit(String key, ObjectNode query) {
        pending.remove(key);
        pending.put(key, query);
        notifyAll();
    }

    /** Forgets the request for {@code key} unless it is acknowledged already (then there is nothing to forget). */
    public synchronized void cancel(String key) {
        pending.remove(key);
    }

    private synchronized Map.Entry<String, ObjectNode> next() throws InterruptedException {
        while (running && pending.isEmpty()) {
            wait(200);
        }
        return running ? pending.entrySet().iterator().next() : null;
    }

    /** Removes the entry unless a newer value was submitted meanwhile. */
    private synchronized void done(String key, ObjectNode query) {
        pending.remove(key, query);
    }

    private synchronized void sleepBackoff(long ms) throws InterruptedException {
        long end = System.currentTimeMillis() + ms;
        long left;
        while (running && (left = end - System.currentTimeMillis()) > 0) {
            wait(left); // submit() wakes us early, harmless: the loop re-checks the deadline
        }
    }

    private void loop() {
        ZMQ.Socket socket = connect();
        // One poller per socket, not per request: opening and closing a selector for every query
        // cost milliseconds on the change-parameter path.
        SocketWait poller = poller(socket);
        LinkMonitor link = new LinkMonitor(ctx, socket);
        Connect.connect(socket, endpoint);
        long backoff = backoffMinMs;
        int attempt = 0;
        try {
            while (running) {
                Map.Entry<String, ObjectNode> e = next();
                if (e == null) {
                    break;
                }
                if (!link.awaitUp(200)) {
                    continue; // not connected yet: nothing is lost, take the newest request again
                }
                ObjectNode message = e.getValue();
                socket.sendMore(new byte[0]);
                socket.send(Json.write(message));
                listener.sent(e.getKey(), message);
                if (awaitAck(socket, poller)) {
                    done(e.getKey(), e.getValue());
                    listener.acked(e.getKey(), message);
                    backoff = backoffMinMs;
                    attempt = 0;
                } else {
                    link.close();
                    poller.close();
                    socket.close(); // drops a late reply with the socket
                    socket = connect(); // connects during the back-off
                    poller = poller(socket);
                    link = new LinkMonitor(ctx, socket);
                    Connect.connect(socket, endpoint);
                    attempt++;
                    listener.retry(e.getKey(), message, attempt, backoff);
                    sleepBackoff(backoff);
                    backoff = Math.min(backoffMaxMs, backoff * 2);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            if (running) {
                LOG.severe(thread.getName() + " stopped: " + e);
            }
        } finally {
            link.close();
            poller.close();
            ctx.close();
        }
    }

    private ZMQ.Socket connect() {
        ZMQ.Socket s = ctx.createSocket(SocketType.DEALER);
        s.setLinger(0);
        return s;
    }

    /** Reads the reply envelope: empty delimiter then the (empty) ack frame. */
    private boolean awaitAck(ZMQ.Socket socket, SocketWait poller) {
        long end = System.currentTimeMillis() + ackTimeoutMs;
        long left;
        boolean ready = false;
        while (running && (left = end - System.currentTimeMillis()) > 0) {
            // Read before waiting: the socket's FD signals a new reply only once a read has found
            // it empty (see SocketWait). One request in flight per socket, so any reply is the ack
            // of this query.
            if (ZMsg.recvMsg(socket, false) != null) {
                return true;
            }
            if (ready) {
                poller.idle(); // the last wake-up had nothing to read: see SocketWait
            }
            ready = poller.await(Math.min(left, 50));
        }
        return false;
    }

    private SocketWait poller(ZMQ.Socket socket) {
        return new SocketWait().add(socket);
    }

    @Override
    public void close() {
        running = false;
        synchronized (this) {
            notifyAll();
        }
        try {
            thread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
