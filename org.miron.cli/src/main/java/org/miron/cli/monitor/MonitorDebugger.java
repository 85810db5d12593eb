package org.miron.cli.monitor;

import java.util.Map;
import java.util.TreeMap;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;

import org.miron.runtime.Json;
import org.miron.runtime.groot.GrootConnection;
import org.miron.runtime.groot.GrootConnection.GrootException;
import org.miron.runtime.groot.GrootConnection.Hook;
import org.miron.runtime.groot.GrootConnection.Mode;
import org.miron.runtime.groot.GrootConnection.Position;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The live page's debugger: a Groot2 client of the executor's Groot2 server (ours or BT.CPP's
 * Groot2Publisher), so the page sets breakpoints and forces results through the very hooks Groot2
 * uses. It polls the server every {@link #POLL_MS} while a page is connected or asks (the hooks and
 * the blackboards; that is also the heartbeat that keeps the hooks enabled), learns from the server's notices where the tree paused,
 * and tells the pages its state as a {@code debug} event whenever it changes. A server that stops
 * answering makes it "detached"; it attaches again, reading the tree anew, when one answers.
 *
 * <p>Step: the tree goes on from where it is paused until just before the root's next tick, i.e. it
 * finishes the tick under way (or runs one whole tick when paused at the root) and pauses again. It
 * is a breakpoint of the debugger's own on the root ({@code stepping}), removed by continue.
 */
final class MonitorDebugger implements AutoCloseable {
    static final long POLL_MS = 500;
    /** Without a page connected, polling stops this long after the last request. */
    private static final long IDLE_NANOS = 5_000_000_000L;
    /** Every this many polls the tree is read again: a new one (another executor) is attached anew. */
    private static final int TREE_EVERY = 10;
    private static final int TIMEOUT_MS = 1500;

    /** A request from the page the debugger cannot do; {@code status} is the HTTP status to answer. */
    static final class Refused extends Exception {
        private static final long serialVersionUID = 1L;
        final int status;

        Refused(int status, String message) {
            super(message);
            this.status = status;
        }
    }

    /** A hook as the server listed it, with the page's node id. */
    private record KnownHook(String node, int uid, Mode mode, Position position, String status, boolean once) {
    }

    private final GrootConnection groot;
    private final Consumer<MonitorState.Event> pages;
    private final BooleanSupplier watched;
    /** When the page last asked something (System.nanoTime()). */
    private volatile long lastAskedNanos = System.nanoTime();
    private final Thread poller;
    private volatile boolean open = true;
    private GrootTreeMap tree;
    /** The server's FULLTREE as last read, and how many polls since the attachment. */
    private String treeXml;
    private long polls;
    private boolean attached;
    private String message = "attaching…";
    private final Map<Integer, KnownHook> hooks = new TreeMap<>();
    private Integer paused;
    /** How many times the tree paused (a new pause at the same node is news to the page). */
    private long pauses;
    /** The root carries the debugger's step breakpoint. */
    private boolean stepping;
    private JsonNode blackboards = Json.MAPPER.createObjectNode();
    private String lastPublished = "";
    /**
     * Counts the states published: an HTTP reply computed before a notice can reach the page after
     * the notice's event, and the page keeps the state of the highest revision.
     */
    private long revision;

    /**
     * Attaches to the Groot2 server on 127.0.0.1:port (and port + 1); {@code pages} gets its events;
     * {@code watched} says whether a page is connected.
     */
    MonitorDebugger(int port, Consumer<MonitorState.Event> pages, BooleanSupplier watched) {
        this.pages = pages;
        this.watched = watched;
        this.groot = new GrootConnection("127.0.0.1", port, TIMEOUT_MS, notice -> {
            Integer uid = GrootConnection.reachedUid(notice);
            if (uid != null) {
                reached(uid);
            }
        });
        poller = new Thread(this::poll, "miron-monitor-groot");
        poller.setDaemon(true);
        poller.start();
    }

    private void poll() {
        while (open) {
            try {
                // Polled only while someone looks: a page that went away stops the requests, and the
                // server's own heartbeat then disables the hooks after 5 s, so a paused tree goes on.
                if (watched.getAsBoolean() || System.nanoTime() - lastAskedNanos < IDLE_NANOS) {
                    refresh();
                }
            } catch (RuntimeException e) {
                if (!open) {
                    return; // closing under a request
                }
                throw e;
            }
            try {
                Thread.sleep(POLL_MS);
            } catch (InterruptedException e) {
                return;
            }
        }
    }

    private synchronized void refresh() {
        try {
            if (attached && ++polls % TREE_EVERY == 0 && !groot.fullTree().equals(treeXml)) {
                detach("attaching to a new tree…"); // an executor restarted with another tree between two polls
            }
            if (!attached) {
                treeXml = groot.fullTree();
                GrootTreeMap read = GrootTreeMap.parse(treeXml);
                // a breakpoint's notice is lost if it goes before the subscriber is there
                groot.awaitSubscriber(2000);
                tree = read;
                attached = true;
                message = "attached to " + groot.address() + " (" + tree.size() + " nodes)";
            }
            readHooks(groot.hooks());
            blackboards = groot.blackboards(tree.blackboards());
        } catch (GrootException e) {
            detach(e.refused() ? e.getMessage() : "detached: " + e.getMessage());
        } catch (IllegalArgumentException e) {
            detach("detached: " + groot.address() + " serves a tree the page cannot read: " + e.getMessage());
        }
        publish();
    }

    private void detach(String why) {
        attached = false;
        tree = null;
        hooks.clear();
        paused = null;
        stepping = false;
        blackboards = Json.MAPPER.createObjectNode();
        message = why;
    }

    private void readHooks(JsonNode dump) {
        hooks.clear();
        for (JsonNode h : dump) {
            int uid = h.path("uid").asInt();
            GrootTreeMap.Entry entry = tree.byUid(uid);
            if (entry != null) {
                hooks.put(uid, new KnownHook(entry.pageId(), uid, Mode.values()[h.path("mode").asInt() == 1 ? 1 : 0],
                        h.path("position").asInt() == 1 ? Position.POST : Position.PRE, h.path("desired_status").asText(),
                        h.path("once").asBoolean()));
            }
        }
        KnownHook at = paused == null ? null : hooks.get(paused);
        if (at == null || at.mode() != Mode.BREAKPOINT) {
            paused = null; // its hook went (another client, the heartbeat) or now forces a result
        }
        stepping &= hooks.containsKey(tree.rootUid());
    }

    /** A hook was reached (the notice thread): a breakpoint pauses the tree, a REPLACE does not. */
    private synchronized void reached(int uid) {
        if (!attached) {
            return;
        }
        KnownHook hook = hooks.get(uid);
        if (hook == null || hook.mode() == Mode.BREAKPOINT) {
            paused = uid; // a hook of another client: taken as a breakpoint until the next dump says
            pauses++;
            publish();
        }
    }

    /** A request from a page came (it keeps the polling on while no page is connected). */
    void asked() {
        lastAskedNanos = System.nanoTime();
    }

    /** Sets a breakpoint on the page's node before (PRE) or after (POST) its tick, once or always. */
    synchronized void breakpoint(String node, Position position, boolean once) throws Refused {
        GrootTreeMap.Entry entry = entry(node);
        insert(new Hook(entry.uid(), Mode.BREAKPOINT, position, "SKIPPED", once));
        if (entry.uid() == tree.rootUid()) {
            stepping = false; // the user's now
        }
    }

    /** Forces the node's result: SUCCESS or FAILURE replace its tick, SKIPPED lets it tick. */
    synchronized void force(String node, String status, boolean once) throws Refused {
        GrootTreeMap.Entry entry = entry(node);
        if (!status.equals("SUCCESS") && !status.equals("FAILURE") && !status.equals("SKIPPED")) {
            throw new Refused(400, "a forced result is SUCCESS, FAILURE or SKIPPED, not " + status);
        }
        insert(new Hook(entry.uid(), Mode.REPLACE, Position.PRE, status, once));
        if (Integer.valueOf(entry.uid()).equals(paused)) {
            paused = null; // a breakpoint turned into a replacement lets its tick go
        }
    }

    /** Removes the node's hook (a paused tick goes on). */
    synchronized void clear(String node) throws Refused {
        GrootTreeMap.Entry entry = entry(node);
        KnownHook hook = hooks.get(entry.uid());
        if (hook == null) {
            throw new Refused(409, "no breakpoint or forced result on " + entry.name());
        }
        call(() -> groot.remove(entry.uid(), Position.PRE));
        if (Integer.valueOf(entry.uid()).equals(paused)) {
            paused = null;
        }
        stepping &= entry.uid() != tree.rootUid();
        refresh();
    }

    /** Lets the paused tree go on (and ends a step). */
    synchronized void resume() throws Refused {
        requireAttached();
        if (paused == null) {
            throw new Refused(409, "the tree is not paused");
        }
        int at = paused;
        int root = tree.rootUid();
        boolean wasStepping = stepping;
        if (stepping) {
            call(() -> groot.remove(root, Position.PRE)); // releases the tick if it waits there
            stepping = false;
        }
        if (!(wasStepping && at == root)) {
            KnownHook hook = hooks.get(at);
            call(() -> groot.unlock(at, Position.PRE, "SKIPPED", hook != null && hook.once()));
        }
        paused = null;
        refresh();
    }

    /** Runs until just before the root's next tick; from a running tree, pauses there. */
    synchronized void step() throws Refused {
        requireAttached();
        int root = tree.rootUid();
        KnownHook onRoot = hooks.get(root);
        if (onRoot != null && onRoot.mode() == Mode.REPLACE) {
            throw new Refused(409, "the root's result is forced: a step needs to pause before its tick");
        }
        if (onRoot == null) {
            insert(new Hook(root, Mode.BREAKPOINT, Position.PRE, "SKIPPED", false));
            stepping = true;
        }
        if (paused != null) {
            int at = paused;
            KnownHook hook = hooks.get(at);
            // the root's breakpoint stays (not removed when done): it pauses the next tick
            call(() -> groot.unlock(at, Position.PRE, "SKIPPED", at != root && hook != null && hook.once()));
            paused = null;
        }
        refresh();
    }

    /** Removes every hook of every client. */
    synchronized void clearAll() throws Refused {
        requireAttached();
        call(groot::removeAllHooks);
        paused = null;
        stepping = false;
        refresh();
    }

    private void insert(Hook hook) throws Refused {
        call(() -> groot.insert(hook));
        refresh();
    }

    private interface Call {
        void run() throws GrootException;
    }

    private void call(Call call) throws Refused {
        try {
            call.run();
        } catch (GrootException e) {
            if (!e.refused()) {
                detach("detached: " + e.getMessage());
                publish();
                throw new Refused(503, "detached: " + e.getMessage());
            }
            throw new Refused(409, e.getMessage());
        }
    }

    private void requireAttached() throws Refused {
        if (!attached) {
            throw new Refused(503, message);
        }
    }

    private GrootTreeMap.Entry entry(String node) throws Refused {
        requireAttached();
        GrootTreeMap.Entry entry = node == null ? null : tree.byPageId(node);
        if (entry == null) {
            throw new Refused(404, "unknown node " + node + ": the tree " + groot.address() + " serves has none with that id");
        }
        return entry;
    }

    /** {"attached","message","server","paused":{node,name,uid}|null,"stepping","pauses","hooks":[...],"blackboards":{},"revision"} */
    synchronized ObjectNode state() {
        return body().put("revision", revision);
    }

    private ObjectNode body() {
        ObjectNode state = Json.MAPPER.createObjectNode();
        state.put("attached", attached).put("message", message).put("server", groot.address());
        GrootTreeMap.Entry at = paused == null || tree == null ? null : tree.byUid(paused);
        if (at == null) {
            state.putNull("paused");
        } else {
            state.putObject("paused").put("node", at.pageId()).put("name", at.name()).put("uid", at.uid());
        }
        state.put("stepping", stepping).put("pauses", pauses);
        ArrayNode list = state.putArray("hooks");
        hooks.values().forEach(h -> list.addObject().put("node", h.node()).put("uid", h.uid())
                .put("name", tree.byUid(h.uid()).name()).put("mode", h.mode().name()).put("position", h.position().name())
                .put("status", h.status()).put("once", h.once())
                .put("step", stepping && h.uid() == tree.rootUid()));
        state.set("blackboards", blackboards == null || blackboards.isNull() ? Json.MAPPER.createObjectNode() : blackboards);
        return state;
    }

    private void publish() {
        String now = body().toString();
        if (!now.equals(lastPublished)) {
            lastPublished = now;
            revision++;
            pages.accept(new MonitorState.Event("debug", state().toString()));
        }
    }

    @Override
    public void close() {
        open = false; // not interrupted: ZeroMQ throws on an interrupted receive; it ends within a request's timeout
        try {
            poller.join(3000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        groot.close();
    }
}
