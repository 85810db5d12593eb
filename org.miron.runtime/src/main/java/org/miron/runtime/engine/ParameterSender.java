package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.logging.Logger;
import org.miron.runtime.Connect;
import org.miron.runtime.Json;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * Sends change-parameter queries through the broker on its own thread, so a slow or absent skill
 * interface never blocks the solve loop. Per parameter only the latest wanted value is kept
 * (bounded memory, a newer decision supersedes a pending one). Each query waits for the ack (the
 * empty reply frame); without it the socket is dropped (stale replies go with it, "lazy pirate")
 * and the query is retried after an exponential back-off.
 *
 * <p>The socket is a DEALER speaking REQ's envelope (empty delimiter, then the body), so a lost
 * reply cannot wedge a REQ state machine; the broker's ROUTER sees an ordinary REQ client.
 */
public final class ParameterSender implements AutoCloseable {
    /** Progress reports, called on the sender thread. */
    public interface Listener {
        void sent(String key, ObjectNode query);

        void acked(String key, ObjectNode query);

        void retry(String key, ObjectNode query, int attempt, long backoffMs);
    }

    private static final Logger LOG = Logger.getLogger(ParameterSender.class.getName());
    private final String endpoint;
    private final long ackTimeoutMs;
    private final long backoffMinMs;
    private final long backoffMaxMs;
    private final Listener listener;
    private final Map<String, ObjectNode> pending = new LinkedHashMap<>();
    private final ZContext ctx = new ZContext();
    private final Thread thread;
    private volatile boolean running = true;
    private long nextId = 1;

    public ParameterSender(String endpoint, long ackTimeoutMs, long backoffMinMs, long backoffMaxMs, Listener listener) {
        this.endpoint = endpoint;
        this.ackTimeoutMs = ackTimeoutMs;
        this.backoffMinMs = backoffMinMs;
        this.backoffMaxMs = backoffMaxMs;
        this.listener = listener;
        this.thread = new Thread(this::loop, "engine-parameters");
        this.thread.setDaemon(true);
    }

    public ParameterSender start() {
        thread.start();
        return this;
    }

    /**
     * Builds the SmartSoft change-parameter query body (without id) for an arch binding. Numbers
     * are sent as doubles, never truncated; anything else (an enum literal) as it is.
     */
    public static ObjectNode changeParameter(Binding arch, JsonNode value) {
        ObjectNode q = Json.object();
        q.put("type", "change-parameter");
        q.put("ParameterSetRepository", arch.text("parameterSetRepository"));
        q.put("ParameterSet", arch.text("parameterSet"));
        q.put("Component", arch.text("component"));
        q.put("Parameter", arch.text("parameter"));
        ObjectNode values = q.putObject("values");
        // As the original MIRoN query: the value in both slots of the parameter (e.g. min and max).
        JsonNode v = value.isNumber() ? DoubleNode.valueOf(value.asDouble()) : value;
        values.set("1", v);
        values.set("2", v);
        return q;
    }

    /** Queues a query for {@code key} (e.g. the varpoint), replacing any not yet acknowledged one. */
    public synchronized void submit(String key, ObjectNode query) {
        pending.remove(key);
        pending.put(key, query);
        notifyAll();
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
        ZMQ.Socket socket = null;
        long backoff = backoffMinMs;
        int attempt = 0;
        try {
            while (running) {
                Map.Entry<String, ObjectNode> e = next();
                if (e == null) {
                    break;
                }
                if (socket == null) {
                    socket = connect();
                }
                ObjectNode message = Json.object();
                message.put("id", nextId++);
                message.put("msg-type", "query");
                message.set("query", e.getValue());
                socket.sendMore(new byte[0]);
                socket.send(Json.write(message));
                listener.sent(e.getKey(), message);
                if (awaitAck(socket)) {
                    done(e.getKey(), e.getValue());
                    listener.acked(e.getKey(), message);
                    backoff = backoffMinMs;
                    attempt = 0;
                } else {
                    socket.close(); // drops a late reply with the socket
                    socket = null;
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
                LOG.severe("parameter sender stopped: " + e);
            }
        } finally {
            ctx.close();
        }
    }

    private ZMQ.Socket connect() {
        ZMQ.Socket s = ctx.createSocket(SocketType.DEALER);
        s.setLinger(0);
        Connect.connect(s, endpoint);
        return s;
    }

    /** Reads the reply envelope: empty delimiter then the (empty) ack frame. */
    private boolean awaitAck(ZMQ.Socket socket) {
        try (ZMQ.Poller poller = ctx.createPoller(1)) {
            poller.register(socket, ZMQ.Poller.POLLIN);
            long end = System.currentTimeMillis() + ackTimeoutMs;
            long left;
            while (running && (left = end - System.currentTimeMillis()) > 0) {
                poller.poll(Math.min(left, 50));
                // One request in flight per socket, so any reply is the ack of this query. The
                // poll only paces the wait; the non-blocking read decides.
                if (ZMsg.recvMsg(socket, false) != null) {
                    return true;
                }
            }
            return false;
        }
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
