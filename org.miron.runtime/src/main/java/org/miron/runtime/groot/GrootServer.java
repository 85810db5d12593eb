package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import org.zeromq.ZMsg;

/**
 * BT.CPP 4's Groot2Publisher for a tree of the Java executor: a REP server on 127.0.0.1:port
 * answering Groot2's requests, a PUB on port + 1 telling it which breakpoint was reached, and the
 * heartbeat that disables every hook when no request came for {@link #heartbeatDelay} (5 s, the
 * library's) and enables them again on the next. Every request gets a reply, a malformed one the
 * library's two-part error ({@code "error"}, the reason), so the REP socket never sticks.
 */
public final class GrootServer implements AutoCloseable {
    public static final Duration DEFAULT_HEARTBEAT_DELAY = Duration.ofSeconds(5);

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Tree tree;
    private final GrootTree numbering;
    private final StatusSnapshot statuses;
    private final GrootHooks hooks;
    private final String xml;
    private final byte[] treeId = GrootProtocol.treeId();
    private final ZContext zmq = new ZContext();
    private final ZMQ.Socket server;
    private final ZMQ.Socket publisher;
    private final Thread serverThread;
    private final Thread heartbeatThread;
    private volatile boolean running = true;
    private final AtomicBoolean closed = new AtomicBoolean();
    private volatile long lastRequestNanos = System.nanoTime();
    private volatile Duration heartbeatDelay = DEFAULT_HEARTBEAT_DELAY;
    private volatile boolean clientAlive = true;

    private GrootServer(Tree tree, int port, DeclaredModels declared) {
        this.tree = tree;
        numbering = new GrootTree(tree);
        statuses = new StatusSnapshot(numbering);
        hooks = new GrootHooks(numbering, this::publishReached);
        xml = GrootTreeXml.write(numbering, declared);
        server = zmq.createSocket(SocketType.REP);
        publisher = zmq.createSocket(SocketType.PUB);
        for (ZMQ.Socket socket : List.of(server, publisher)) {
            socket.setLinger(0);
            socket.setSendTimeOut(1000);
        }
        server.setReceiveTimeOut(100);
        try {
            server.bind("tcp://127.0.0.1:" + port);
            publisher.bind("tcp://127.0.0.1:" + (port + 1));
        } catch (RuntimeException e) {
            zmq.close();
            throw e;
        }
        tree.addListener(statuses);
        tree.context().setTickHook(hooks);
        serverThread = new Thread(this::serve, "groot-server-" + port);
        heartbeatThread = new Thread(this::heartbeat, "groot-heartbeat-" + port);
        serverThread.setDaemon(true);
        heartbeatThread.setDaemon(true);
        serverThread.start();
        heartbeatThread.start();
    }

    /** Serves Groot2 for this tree on 127.0.0.1:port and port + 1 (attach before the tree runs). */
    public static GrootServer start(Tree tree, int port) {
        return start(tree, port, null);
    }

    /** The same, the application's node models as {@code treeFile}'s TreeNodesModel declares them (null: none). */
    public static GrootServer start(Tree tree, int port, Path treeFile) {
        if (port < 1 || port > 65534) {
            throw new IllegalArgumentException("the Groot2 port must be 1 to 65534 (it uses the next one too): " + port);
        }
        return new GrootServer(tree, port, treeFile == null ? DeclaredModels.none() : DeclaredModels.of(treeFile));
    }

    /** How long without a request before the hooks are disabled (tests shorten it). */
    public GrootServer heartbeatDelay(Duration delay) {
        heartbeatDelay = delay;
        return this;
    }

    /** The tree with uids, as FULLTREE answers. */
    public String treeXml() {
        return xml;
    }

    private void serve() {
        while (running) {
            ZMsg request = ZMsg.recvMsg(server, true);
            if (request == null) {
                continue; // the 100 ms receive timeout: look at running again
            }
            lastRequestNanos = System.nanoTime();
            List<byte[]> parts = new ArrayList<>();
            request.forEach(frame -> parts.add(frame.getData()));
            request.destroy();
            List<byte[]> reply;
            try {
                reply = answer(parts);
            } catch (RuntimeException e) {
                // the library would throw out of its server thread here; we answer and go on
                reply = error(e.getMessage() == null ? e.toString() : e.getMessage());
            }
            ZMsg out = new ZMsg();
            reply.forEach(out::add);
            out.send(server, true);
        }
    }

    private List<byte[]> answer(List<byte[]> parts) {
        GrootProtocol.Header header = GrootProtocol.Header.parse(parts.get(0));
        if (header == null) {
            return error("wrong request header");
        }
        List<byte[]> reply = new ArrayList<>();
        reply.add(header.reply(treeId));
        switch (header.type()) {
        case GrootProtocol.FULLTREE -> reply.add(xml.getBytes(StandardCharsets.UTF_8));
        case GrootProtocol.STATUS -> reply.add(statuses.snapshot());
        case GrootProtocol.BLACKBOARD -> {
            if (parts.size() != 2) {
                return error("must be 2 parts message");
            }
            reply.add(BlackboardDump.reply(numbering, text(parts.get(1))));
        }
        case GrootProtocol.HOOK_INSERT -> {
            if (parts.size() != 2) {
                return error("must be 2 parts message");
            }
            JsonNode json = json(parts.get(1));
            List<GrootHook.HookJson> inserted = new ArrayList<>();
            for (JsonNode one : json.isArray() ? json : List.of(json)) {
                inserted.add(GrootHook.HookJson.parse(one));
            }
            inserted.forEach(hooks::insert);
        }
        case GrootProtocol.BREAKPOINT_UNLOCK -> {
            if (parts.size() != 2) {
                return error("must be 2 parts message");
            }
            JsonNode json = json(parts.get(1));
            int uid = GrootHook.uid(json, "uid");
            String status = GrootHook.text(json, "desired_status");
            int position = GrootHook.integer(json, "position");
            boolean remove = GrootHook.bool(json, "remove_when_done");
            // as the library: SUCCESS or FAILURE force the result, anything else lets the node tick
            NodeStatus result = status.equals("SUCCESS") ? NodeStatus.SUCCESS
                    : status.equals("FAILURE") ? NodeStatus.FAILURE : NodeStatus.SKIPPED;
            if (!hooks.unlock(position, uid, result, remove)) {
                return error("Node ID not found");
            }
        }
        case GrootProtocol.REMOVE_ALL_HOOKS -> hooks.removeAll();
        case GrootProtocol.DISABLE_ALL_HOOKS -> hooks.enableAll(false);
        case GrootProtocol.HOOK_REMOVE -> {
            if (parts.size() != 2) {
                return error("must be 2 parts message");
            }
            JsonNode json = json(parts.get(1));
            if (!hooks.remove(GrootHook.integer(json, "position"), GrootHook.uid(json, "uid"))) {
                return error("Node ID not found");
            }
        }
        case GrootProtocol.HOOKS_DUMP -> reply.add(hooks.dump().toString().getBytes(StandardCharsets.UTF_8));
        case GrootProtocol.TOGGLE_RECORDING -> {
            if (parts.size() != 2) {
                return error("must be 2 parts message");
            }
            String command = text(parts.get(1));
            if (command.equals("start")) {
                reply.add(Long.toString(statuses.startRecording()).getBytes(StandardCharsets.UTF_8));
            } else if (command.equals("stop")) {
                statuses.stopRecording();
            }
        }
        case GrootProtocol.GET_TRANSITIONS -> reply.add(statuses.takeTransitions());
        default -> {
            return error("Request not recognized");
        }
        }
        return reply;
    }

    private static List<byte[]> error(String reason) {
        return List.of("error".getBytes(StandardCharsets.UTF_8), reason.getBytes(StandardCharsets.UTF_8));
    }

    private static String text(byte[] part) {
        return new String(part, StandardCharsets.UTF_8);
    }

    private static JsonNode json(byte[] part) {
        try {
            JsonNode json = JSON.readTree(part);
            if (json == null || json.isMissingNode()) {
                throw new IllegalArgumentException("empty JSON");
            }
            return json;
        } catch (IOException e) {
            throw new IllegalArgumentException("malformed JSON: " + e.getMessage());
        }
    }

    /** On the tick thread, inside a hook: BREAKPOINT_REACHED with the node's uid in decimal. */
    private void publishReached(int uid) {
        byte[] header = GrootProtocol.notice(GrootProtocol.BREAKPOINT_REACHED).bytes();
        synchronized (publisher) {
            if (running) {
                publisher.sendMore(header);
                publisher.send(Integer.toString(uid));
            }
        }
    }

    private void heartbeat() {
        boolean alive = true;
        while (running) {
            try {
                Thread.sleep(10);
            } catch (InterruptedException e) {
                return;
            }
            boolean now = System.nanoTime() - lastRequestNanos < heartbeatDelay.toNanos();
            if (now != alive) {
                alive = now;
                hooks.enableAll(alive);
                clientAlive = alive;
            }
        }
    }

    /** False once the heartbeat has disabled the hooks (no request for the delay), true again after the next. */
    public boolean clientAlive() {
        return clientAlive;
    }

    /** Removes every hook (a paused tree goes on), detaches from the tree and closes the sockets. */
    @Override
    public void close() {
        if (!closed.compareAndSet(false, true)) {
            return;
        }
        hooks.removeAll();
        tree.context().setTickHook(null);
        tree.context().removeListener(statuses);
        running = false;
        heartbeatThread.interrupt();
        try {
            serverThread.join(2000);
            heartbeatThread.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        synchronized (publisher) {
            zmq.close();
        }
    }
}
