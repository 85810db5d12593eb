package org.miron.cli.monitor;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.UnaryOperator;

import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;

/**
 * The live monitor: an HTTP server on 127.0.0.1 (the JDK's) serving the page of a running tree
 * ({@code /}), its state as JSON ({@code /state}) and every change as server-sent events
 * ({@code /events}). It follows the bus, not an executor: statuses come from whichever executor
 * publishes {@code miron.bt.status}, so the page survives an executor stopping and a new one
 * starting (and a restarted broker, which the bus client reconnects to); a page that loses the
 * server reconnects by itself (EventSource) and gets the whole state again.
 */
public final class MonitorServer implements AutoCloseable {
    /** A page that stops reading is dropped once this many events wait for it. */
    private static final int CLIENT_QUEUE = 10_000;
    /** A comment line this often keeps idle connections open and finds closed ones. */
    private static final long KEEPALIVE_MS = 5000;

    private final HttpServer server;
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "miron-monitor-http");
        t.setDaemon(true);
        return t;
    });
    private final MonitorState state;
    private final BusClient bus;
    private final byte[] page;
    private volatile boolean open = true;
    /** Breakpoints and forced results, once attached to a Groot2 server ({@link #attachGroot}). */
    private volatile MonitorDebugger debugger;
    private volatile DebugRoutes debug = new DebugRoutes(null);

    /**
     * Starts serving on 127.0.0.1:{@code port} (0: any free port) the page {@code html} and the state
     * read from the bus at {@code busIn}/{@code busOut}.
     */
    public MonitorServer(int port, String html, String busIn, String busOut, UnaryOperator<String> metricName)
            throws IOException {
        this.page = html.getBytes(StandardCharsets.UTF_8);
        this.state = new MonitorState(metricName);
        this.server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 0);
        server.setExecutor(threads);
        server.createContext("/", this::page);
        server.createContext("/state", this::state);
        server.createContext("/events", this::events);
        server.createContext("/debug/", exchange -> debug.handle(exchange));
        this.bus = new BusClient("monitor", busIn, busOut, List.of(Topics.BT_STATUS, Topics.BT_TREE, Topics.REQUIREMENT, Topics.VARIANT_PREFIX,
                Topics.BLACKBOARD_PREFIX, Topics.DECISION, Topics.ESTIMATE), state::onBus);
        bus.start();
        server.start();
    }

    /** The port it listens on. */
    public int port() {
        return server.getAddress().getPort();
    }

    public String url() {
        return "http://127.0.0.1:" + port() + "/";
    }

    private void page(HttpExchange exchange) throws IOException {
        HttpReplies.page(exchange, page);
    }

    private void state(HttpExchange exchange) throws IOException {
        HttpReplies.reply(exchange, 200, "application/json", state.snapshot().toString().getBytes(StandardCharsets.UTF_8));
    }

    /** One page's event stream, until it goes away or the server closes. */
    private void events(HttpExchange exchange) throws IOException {
        BlockingQueue<MonitorState.Event> queue = new ArrayBlockingQueue<>(CLIENT_QUEUE);
        MonitorState.Subscriber subscriber = event -> {
            if (!queue.offer(event)) {
                queue.clear(); // too far behind: start again from the whole state
                queue.offer(new MonitorState.Event("snapshot", state.snapshot().toString()));
            }
        };
        exchange.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        exchange.sendResponseHeaders(200, 0);
        OutputStream out = exchange.getResponseBody();
        state.subscribe(subscriber);
        try {
            out.write("retry: 1000\n\n".getBytes(StandardCharsets.UTF_8));
            out.flush();
            while (open) {
                MonitorState.Event event = queue.poll(KEEPALIVE_MS, TimeUnit.MILLISECONDS);
                String text = event == null ? ": keep-alive\n\n" : "event: " + event.name() + "\ndata: " + event.data() + "\n\n";
                out.write(text.getBytes(StandardCharsets.UTF_8));
                out.flush();
            }
        } catch (IOException | InterruptedException gone) {
            // the page went away (or the server is closing)
        } finally {
            state.unsubscribe(subscriber);
            try {
                out.close();
            } catch (IOException ignored) {
                // already closed by the client
            }
        }
    }

    /**
     * Debugs through the Groot2 server on 127.0.0.1:{@code grootPort} (the executor's, Java or
     * BehaviorTree.CPP): the page's breakpoints and forced results become that server's hooks.
     */
    public MonitorServer attachGroot(int grootPort) {
        if (debugger != null) {
            throw new IllegalStateException("already attached to a Groot2 server");
        }
        debugger = new MonitorDebugger(grootPort, state::publish, () -> state.subscribers() > 0);
        debug = new DebugRoutes(debugger);
        return this;
    }

    /** Pages connected now (tests wait for theirs). */
    public int connectedPages() {
        return state.subscribers();
    }

    @Override
    public void close() {
        open = false;
        if (debugger != null) {
            debugger.close();
        }
        server.stop(0);
        bus.close();
        threads.shutdownNow();
    }
}
