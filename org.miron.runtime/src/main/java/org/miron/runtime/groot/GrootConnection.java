package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.msgpack.jackson.dataformat.MessagePackMapper;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * A client of a Groot2 server, BT.CPP's Groot2Publisher or our {@link GrootServer}, as Groot2 talks
 * to one: requests on a REQ to host:port, BREAKPOINT_REACHED notices on a SUB to port + 1. A request
 * not answered within the timeout fails and the REQ socket is made again (a REQ that lost its reply
 * would refuse every later send), so a server that goes away and comes back is simply asked again.
 * Requests are serialised (a ZeroMQ socket is used by one thread at a time).
 */
public final class GrootConnection implements AutoCloseable {
    /** A hook as HOOK_INSERT sends it. */
    public record Hook(int uid, Mode mode, Position position, String desiredStatus, boolean once) {
        JsonNode toJson() {
            ObjectNode json = JSON.createObjectNode();
            json.put("uid", uid).put("mode", mode.ordinal()).put("position", position.ordinal())
                    .put("desired_status", desiredStatus).put("once", once).put("enabled", true);
            return json;
        }
    }

    /** The protocol's hook modes, in its numbering. */
    public enum Mode {
        BREAKPOINT, REPLACE
    }

    /** The protocol's hook positions, in its numbering. */
    public enum Position {
        PRE, POST
    }

    /** A request that got no answer in time, or the server's error reply. */
    public static final class GrootException extends IOException {
        private static final long serialVersionUID = 1L;
        private final boolean refused;

        GrootException(String message, boolean refused) {
            super(message);
            this.refused = refused;
        }

        /** True for the server's error reply (it answered: "Node ID not found"...), false for no answer. */
        public boolean refused() {
            return refused;
        }
    }

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final MessagePackMapper MSGPACK = new MessagePackMapper();
    private static final AtomicInteger IDS = new AtomicInteger(1);

    private final ZContext zmq = new ZContext();
    private final String address;
    private final String noticeAddress;
    private int timeoutMs;
    private final ZMQ.Socket handshakes;
    private final Thread noticeThread;
    private volatile boolean open = true;
    private ZMQ.Socket requests;

    /**
     * Connects to the server at host:port (ZeroMQ connects when the server is there, and again when
     * it comes back); {@code notices} gets every message of the server's PUB as it came (frames), on
     * a thread of its own: {@link #reachedUid} reads a BREAKPOINT_REACHED.
     */
    public GrootConnection(String host, int port, int timeoutMs, Consumer<List<byte[]>> notices) {
        this.address = "tcp://" + host + ":" + port;
        this.noticeAddress = "tcp://" + host + ":" + (port + 1);
        this.timeoutMs = timeoutMs;
        ZMQ.Socket subscriber = zmq.createSocket(SocketType.SUB);
        subscriber.setLinger(0);
        subscriber.setReceiveTimeOut(100);
        subscriber.subscribe(new byte[0]);
        String monitor = "inproc://groot-connection-" + IDS.incrementAndGet();
        subscriber.monitor(monitor, ZMQ.EVENT_HANDSHAKE_PROTOCOL);
        handshakes = zmq.createSocket(SocketType.PAIR);
        handshakes.connect(monitor);
        subscriber.connect(noticeAddress);
        requests = newRequestSocket();
        noticeThread = new Thread(() -> readNotices(subscriber, notices), "groot-notices-" + port);
        noticeThread.setDaemon(true);
        noticeThread.start();
    }

    private ZMQ.Socket newRequestSocket() {
        ZMQ.Socket socket = zmq.createSocket(SocketType.REQ);
        socket.setLinger(0);
        socket.setReceiveTimeOut(timeoutMs);
        socket.setSendTimeOut(timeoutMs);
        socket.connect(address);
        return socket;
    }

    private void readNotices(ZMQ.Socket subscriber, Consumer<List<byte[]>> notices) {
        while (open) {
            ZMsg notice;
            try {
                notice = ZMsg.recvMsg(subscriber, true);
            } catch (RuntimeException closing) {
                return; // the context is closing
            }
            if (notice != null) {
                List<byte[]> frames = new ArrayList<>();
                notice.forEach(frame -> frames.add(frame.getData()));
                notice.destroy();
                notices.accept(frames);
            }
        }
    }

    /** The node uid of a BREAKPOINT_REACHED notice (header, uid in decimal), or null for anything else. */
    public static Integer reachedUid(List<byte[]> notice) {
        if (notice.size() != 2 || notice.get(0).length != GrootProtocol.REQUEST_HEADER_SIZE
                || notice.get(0)[1] != GrootProtocol.BREAKPOINT_REACHED) {
            return null;
        }
        try {
            return Integer.parseInt(text(notice.get(1)).trim());
        } catch (NumberFormatException malformed) {
            return null;
        }
    }

    /** How long a request waits for its reply from now on. */
    public synchronized GrootConnection timeoutMs(int ms) {
        timeoutMs = ms;
        requests.setReceiveTimeOut(ms);
        requests.setSendTimeOut(ms);
        return this;
    }

    /**
     * Waits until the notice subscriber has shaken hands with the server's publisher: a PUB drops
     * what it sends before the subscriber is there, so a client that sets a breakpoint waits first.
     */
    public boolean awaitSubscriber(int withinMs) {
        handshakes.setReceiveTimeOut(withinMs);
        return ZMQ.Event.recv(handshakes) != null;
    }

    /** The server's address, for messages. */
    public String address() {
        return address.substring("tcp://".length());
    }

    /** FULLTREE: the tree with its uids, as XML. */
    public String fullTree() throws GrootException {
        return text(request(GrootProtocol.FULLTREE).get(1));
    }

    /** BLACKBOARD: each named subtree instance's entries, as the server's JSON (null: none). */
    public JsonNode blackboards(Collection<String> names) throws GrootException {
        List<byte[]> reply = request(GrootProtocol.BLACKBOARD, String.join(";", names));
        try {
            return MSGPACK.readTree(reply.get(1));
        } catch (IOException e) {
            throw new GrootException("the blackboard reply of " + address() + " is not MessagePack: " + e.getMessage(), true);
        }
    }

    /** HOOKS_DUMP: every hook as the server lists it. */
    public JsonNode hooks() throws GrootException {
        return json(request(GrootProtocol.HOOKS_DUMP).get(1));
    }

    public void insert(Hook hook) throws GrootException {
        request(GrootProtocol.HOOK_INSERT, hook.toJson().toString());
    }

    public void remove(int uid, Position position) throws GrootException {
        request(GrootProtocol.HOOK_REMOVE, JSON.createObjectNode().put("uid", uid).put("position", position.ordinal()).toString());
    }

    /** BREAKPOINT_UNLOCK: SUCCESS or FAILURE force the result, anything else lets the node tick. */
    public void unlock(int uid, Position position, String desiredStatus, boolean removeWhenDone) throws GrootException {
        request(GrootProtocol.BREAKPOINT_UNLOCK, JSON.createObjectNode().put("uid", uid).put("position", position.ordinal())
                .put("desired_status", desiredStatus).put("remove_when_done", removeWhenDone).toString());
    }

    public void removeAllHooks() throws GrootException {
        request(GrootProtocol.REMOVE_ALL_HOOKS);
    }

    /** Sends a request of this type with these text parts; its reply's parts (the header first). */
    public List<byte[]> request(byte type, String... parts) throws GrootException {
        List<byte[]> message = new ArrayList<>();
        message.add(new GrootProtocol.Header(GrootProtocol.PROTOCOL_ID, type, IDS.incrementAndGet()).bytes());
        Arrays.stream(parts).forEach(part -> message.add(part.getBytes(StandardCharsets.UTF_8)));
        List<byte[]> out = raw(message);
        if (out == null) {
            throw new GrootException("no answer from the Groot2 server at " + address() + " within " + timeoutMs + " ms", false);
        }
        if (out.size() == 2 && text(out.get(0)).equals("error")) {
            throw new GrootException(address() + " refused: " + text(out.get(1)), true);
        }
        byte[] first = out.get(0);
        if (first.length != GrootProtocol.REPLY_HEADER_SIZE || first[1] != type) {
            throw new GrootException(address() + " answered with a reply that is not Groot2's", true);
        }
        if (out.size() < 2 && (type == GrootProtocol.FULLTREE || type == GrootProtocol.BLACKBOARD
                || type == GrootProtocol.HOOKS_DUMP)) {
            throw new GrootException(address() + " answered without a body", true);
        }
        return out;
    }

    /**
     * Sends these parts as they are (a test sends malformed requests so); the reply's parts, or null
     * when none came in time (the REQ socket is then made again).
     */
    public synchronized List<byte[]> raw(List<byte[]> parts) throws GrootException {
        if (!open) {
            throw new GrootException("the connection to " + address() + " is closed", false);
        }
        ZMsg message = new ZMsg();
        parts.forEach(message::add);
        ZMsg reply = message.send(requests, true) ? ZMsg.recvMsg(requests) : null;
        if (reply == null) {
            zmq.destroySocket(requests);
            requests = newRequestSocket();
            return null;
        }
        List<byte[]> out = new ArrayList<>();
        reply.forEach(frame -> out.add(frame.getData()));
        reply.destroy();
        return out;
    }

    private static String text(byte[] part) {
        return new String(part, StandardCharsets.UTF_8);
    }

    private JsonNode json(byte[] part) throws GrootException {
        try {
            return JSON.readTree(part);
        } catch (IOException e) {
            throw new GrootException(address() + " answered with malformed JSON: " + e.getMessage(), true);
        }
    }

    @Override
    public void close() {
        open = false;
        try {
            noticeThread.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (this) {
            zmq.close();
        }
    }
}
