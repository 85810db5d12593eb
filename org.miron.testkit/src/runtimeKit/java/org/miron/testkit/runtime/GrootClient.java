package org.miron.testkit.runtime;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.miron.runtime.FreePorts;
import org.miron.runtime.groot.GrootConnection;

/**
 * A Groot2 client for tests, as Groot2 talks to a Groot2Publisher (BT.CPP's or ours): the
 * runtime's {@link GrootConnection} (a REQ on 127.0.0.1:port, a SUB on port + 1), with the raw
 * requests and replies a test sends and reads, and the notices queued until it asks. A request not
 * answered in time returns null and the REQ socket is made again, so the next request can be sent.
 */
public final class GrootClient implements AutoCloseable {
    private static final AtomicInteger IDS = new AtomicInteger(0x1000);

    private final BlockingQueue<List<byte[]>> notices = new LinkedBlockingQueue<>();
    private final GrootConnection connection;

    public GrootClient(int port) {
        connection = new GrootConnection("127.0.0.1", port, 5000, notices::add);
    }

    /**
     * Waits until the notice subscriber has finished its handshake with the publisher: a PUB drops
     * what it sends before a subscriber is there, so a test that expects a notice waits for this first.
     */
    public boolean awaitSubscriber(int withinMs) {
        return connection.awaitSubscriber(withinMs);
    }

    /** A port P with P + 1 free too (both are bound by a publisher), below the ephemeral range. */
    public static int freePortPair() throws IOException {
        InetAddress lo = InetAddress.getLoopbackAddress();
        for (int i = 0; i < 50; i++) {
            try (ServerSocket a = new ServerSocket(FreePorts.take(1)[0], 1, lo);
                    ServerSocket b = new ServerSocket(a.getLocalPort() + 1, 1, lo)) {
                return a.getLocalPort();
            } catch (BindException taken) {
                // P + 1 is in use: try another P
            }
        }
        throw new IOException("no two consecutive free ports on the loopback");
    }

    public GrootClient timeoutMs(int ms) {
        connection.timeoutMs(ms);
        return this;
    }

    /** A request header: protocol 2, the type, a fresh unique id (little-endian). */
    public static byte[] header(byte type, int uniqueId) {
        return ByteBuffer.allocate(6).order(ByteOrder.LITTLE_ENDIAN).put((byte) 2).put(type).putInt(uniqueId).array();
    }

    /** Sends a request of this type with these text parts after the header; the reply's parts, or null. */
    public List<byte[]> request(char type, String... parts) {
        List<byte[]> message = new ArrayList<>();
        message.add(header((byte) type, IDS.incrementAndGet()));
        for (String part : parts) {
            message.add(part.getBytes(StandardCharsets.UTF_8));
        }
        return raw(message);
    }

    /** Sends these parts as they are; the reply's parts, or null when none came in time. */
    public List<byte[]> raw(List<byte[]> parts) {
        try {
            return connection.raw(parts);
        } catch (GrootConnection.GrootException closed) {
            return null;
        }
    }

    /** Asks until answered (a publisher starting up may miss the first requests). */
    public List<byte[]> requestUntilAnswered(char type, long withinMs, String... parts) {
        long end = System.currentTimeMillis() + withinMs;
        List<byte[]> reply;
        do {
            reply = request(type, parts);
        } while (reply == null && System.currentTimeMillis() < end);
        return reply;
    }

    /** The next notice on the PUB (header, uid), or null after timeoutMs. */
    public List<byte[]> awaitNotice(int timeoutMs) {
        try {
            return notices.poll(timeoutMs, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    /** Forgets the notices received so far. */
    public void drainNotices() {
        while (awaitNotice(50) != null) {
            // skip
        }
    }

    public static String text(byte[] part) {
        return new String(part, StandardCharsets.UTF_8);
    }

    @Override
    public void close() {
        connection.close();
    }
}
