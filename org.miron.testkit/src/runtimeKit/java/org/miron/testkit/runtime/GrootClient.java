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
import java.util.concurrent.atomic.AtomicInteger;
import org.miron.runtime.FreePorts;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * A Groot2 client for tests, as Groot2 talks to a Groot2Publisher (BT.CPP's or ours): a REQ on
 * 127.0.0.1:port for requests, a SUB on port + 1 for BREAKPOINT_REACHED. A request not answered in
 * time returns null and the REQ socket is made again, so the next request can be sent.
 */
public final class GrootClient implements AutoCloseable {
    private static final AtomicInteger IDS = new AtomicInteger(0x1000);

    private final ZContext zmq = new ZContext();
    private final int port;
    private final ZMQ.Socket notices;
    private final ZMQ.Socket noticeEvents;
    private ZMQ.Socket requests;
    private int timeoutMs = 5000;

    public GrootClient(int port) {
        this.port = port;
        notices = zmq.createSocket(SocketType.SUB);
        notices.setLinger(0);
        notices.subscribe(new byte[0]);
        String monitor = "inproc://groot-client-" + IDS.incrementAndGet();
        notices.monitor(monitor, ZMQ.EVENT_HANDSHAKE_PROTOCOL);
        noticeEvents = zmq.createSocket(SocketType.PAIR);
        noticeEvents.connect(monitor);
        notices.connect("tcp://127.0.0.1:" + (port + 1));
        requests = newRequestSocket();
    }

    /**
     * Waits until the notice subscriber has finished its handshake with the publisher: a PUB drops
     * what it sends before a subscriber is there, so a test that expects a notice waits for this first.
     */
    public boolean awaitSubscriber(int withinMs) {
        noticeEvents.setReceiveTimeOut(withinMs);
        return ZMQ.Event.recv(noticeEvents) != null;
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
        timeoutMs = ms;
        requests.setReceiveTimeOut(ms);
        return this;
    }

    private ZMQ.Socket newRequestSocket() {
        ZMQ.Socket socket = zmq.createSocket(SocketType.REQ);
        socket.setLinger(0);
        socket.setReceiveTimeOut(timeoutMs);
        socket.connect("tcp://127.0.0.1:" + port);
        return socket;
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
        ZMsg message = new ZMsg();
        parts.forEach(message::add);
        if (!message.send(requests, true)) {
            reset();
            return null;
        }
        ZMsg reply = ZMsg.recvMsg(requests);
        if (reply == null) {
            reset();
            return null;
        }
        List<byte[]> out = new ArrayList<>();
        reply.forEach(frame -> out.add(frame.getData()));
        reply.destroy();
        return out;
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

    private void reset() {
        zmq.destroySocket(requests);
        requests = newRequestSocket();
    }

    /** The next notice on the PUB (header, uid), or null after timeoutMs. */
    public List<byte[]> awaitNotice(int timeoutMs) {
        notices.setReceiveTimeOut(timeoutMs);
        ZMsg notice = ZMsg.recvMsg(notices);
        if (notice == null) {
            return null;
        }
        List<byte[]> out = new ArrayList<>();
        notice.forEach(frame -> out.add(frame.getData()));
        notice.destroy();
        return out;
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
        zmq.close();
    }
}
