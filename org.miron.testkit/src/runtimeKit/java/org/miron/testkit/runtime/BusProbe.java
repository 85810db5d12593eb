package org.miron.testkit.runtime;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.miron.runtime.Connect;
import org.miron.runtime.Json;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/** A test subscriber on the broker's XPUB that records every message and lets tests wait for one. */
public final class BusProbe implements AutoCloseable {
    /** A received bus message with its JSON body (null when the body is not JSON). */
    public static final class Message { // a class, not a record: Gradle 4.4.1 cannot scan records
        final String topic;
        final JsonNode body;
        final long receivedNanos;

        Message(String topic, JsonNode body, long receivedNanos) {
            this.topic = topic;
            this.body = body;
            this.receivedNanos = receivedNanos;
        }

        /** System.nanoTime() when the probe received it (benchmarks time start-up by it). */
        public long receivedNanos() {
            return receivedNanos;
        }

        public String topic() {
            return topic;
        }

        public JsonNode body() {
            return body;
        }
    }

    private final ZContext ctx = new ZContext();
    private final List<Message> received = new ArrayList<>();
    private final Thread thread;
    private volatile boolean running = true;

    public BusProbe(String busOut, String... prefixes) {
        ZMQ.Socket sub = ctx.createSocket(SocketType.SUB);
        sub.setLinger(0);
        sub.setReceiveTimeOut(50);
        Connect.connect(sub, busOut);
        for (String p : prefixes) {
            sub.subscribe(p.getBytes(StandardCharsets.UTF_8));
        }
        thread = new Thread(() -> {
            while (running) {
                byte[] topic;
                try {
                    topic = sub.recv();
                } catch (RuntimeException e) {
                    return;
                }
                if (topic == null) {
                    continue;
                }
                long at = System.nanoTime();
                String body = sub.hasReceiveMore() ? sub.recvStr() : "";
                JsonNode json;
                try {
                    json = Json.MAPPER.readTree(body);
                } catch (IOException e) {
                    json = null;
                }
                synchronized (this) {
                    received.add(new Message(new String(topic, StandardCharsets.UTF_8), json, at));
                    notifyAll();
                }
            }
        }, "bus-probe");
        thread.setDaemon(true);
        thread.start();
    }

    /** First message (oldest first) on {@code topic} whose body satisfies {@code p}, or null on timeout. */
    public synchronized JsonNode await(String topic, Predicate<JsonNode> p, long timeoutMs) throws InterruptedException {
        Message m = awaitMessage(topic, p, timeoutMs);
        return m == null ? null : m.body();
    }

    /** The same, the message with its receive time. */
    public synchronized Message awaitMessage(String topic, Predicate<JsonNode> p, long timeoutMs) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (true) {
            for (Message m : received) {
                if (m.topic().equals(topic) && m.body() != null && p.test(m.body())) {
                    return m;
                }
            }
            long left = end - System.currentTimeMillis();
            if (left <= 0) {
                return null;
            }
            wait(left);
        }
    }

    /** Every message so far, in the order received. */
    public synchronized List<Message> messages() {
        return List.copyOf(received);
    }

    public synchronized List<Message> messages(String topic) {
        return received.stream().filter(m -> m.topic().equals(topic)).toList();
    }

    @Override
    public void close() {
        running = false;
        try {
            thread.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        ctx.close();
    }
}
