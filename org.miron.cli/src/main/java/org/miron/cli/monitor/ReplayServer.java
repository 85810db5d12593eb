package org.miron.cli.monitor;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * The live page over a recording ({@code miron replay --monitor PORT}): the JDK's HTTP server on
 * 127.0.0.1 serving the page ({@code /}), the state at an instant ({@code /state?at=MS}) and the
 * live page's event stream ({@code /events}), which sends the state at the replay's instant as a
 * {@code snapshot}, the event a live page gets when it connects, again each time
 * {@code /seek?at=MS} moves the instant (so the live page's own script draws a replayed instant
 * as a live one). Every page open on the replay follows the same instant.
 */
public final class ReplayServer implements AutoCloseable {
    private static final long KEEPALIVE_MS = 5000;

    private final HttpServer server;
    private final ExecutorService threads = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "miron-replay-http");
        t.setDaemon(true);
        return t;
    });
    private final ReplayState replay;
    private final byte[] page;
    private final List<BlockingQueue<String>> pages = new CopyOnWriteArrayList<>();
    private volatile long at;
    private volatile boolean open = true;

    public ReplayServer(int port, String html, ReplayState replay) throws IOException {
        this.page = html.getBytes(StandardCharsets.UTF_8);
        this.replay = replay;
        server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 0);
        server.setExecutor(threads);
        server.createContext("/", this::page);
        server.createContext("/state", exchange -> HttpReplies.reply(exchange, 200, "application/json", state(instant(exchange, at))));
        server.createContext("/seek", this::seek);
        server.createContext("/events", this::events);
        server.start();
    }

    public int port() {
        return server.getAddress().getPort();
    }

    public String url() {
        return "http://127.0.0.1:" + port() + "/";
    }

    private byte[] state(long atMillis) {
        return replay.snapshot(atMillis).toString().getBytes(StandardCharsets.UTF_8);
    }

    private void page(HttpExchange exchange) throws IOException {
        HttpReplies.page(exchange, page);
    }

    /** Moves the instant every page shows; answers the state there. */
    private void seek(HttpExchange exchange) throws IOException {
        long to = instant(exchange, -1);
        if (to < 0) {
            HttpReplies.reply(exchange, 400, "text/plain", "seek?at=MS: milliseconds since the recording started\n".getBytes(StandardCharsets.UTF_8));
            return;
        }
        at = to;
        byte[] state = state(to);
        String data = new String(state, StandardCharsets.UTF_8);
        pages.forEach(q -> q.offer(data));
        HttpReplies.reply(exchange, 200, "application/json", state);
    }

    /** {@code at=MS} of the query, clamped to the recording; {@code otherwise} when absent or not a number. */
    private long instant(HttpExchange exchange, long otherwise) {
        String query = exchange.getRequestURI().getQuery();
        if (query != null) {
            for (String part : query.split("&")) {
                if (part.startsWith("at=")) {
                    try {
                        return Math.min(Math.max(0, Long.parseLong(part.substring(3))), replay.durationMillis());
                    } catch (NumberFormatException e) {
                        return otherwise;
                    }
                }
            }
        }
        return otherwise;
    }

    private void events(HttpExchange exchange) throws IOException {
        BlockingQueue<String> queue = new LinkedBlockingQueue<>();
        queue.offer(new String(state(at), StandardCharsets.UTF_8));
        exchange.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        exchange.sendResponseHeaders(200, 0);
        OutputStream out = exchange.getResponseBody();
        pages.add(queue);
        try {
            out.write("retry: 1000\n\n".getBytes(StandardCharsets.UTF_8));
            out.flush();
            while (open) {
                String snapshot = queue.poll(KEEPALIVE_MS, TimeUnit.MILLISECONDS);
                String text = snapshot == null ? ": keep-alive\n\n" : "event: snapshot\ndata: " + snapshot + "\n\n";
                out.write(text.getBytes(StandardCharsets.UTF_8));
                out.flush();
            }
        } catch (IOException | InterruptedException gone) {
            // the page went away (or the server is closing)
        } finally {
            pages.remove(queue);
            try {
                out.close();
            } catch (IOException ignored) {
                // already closed by the client
            }
        }
    }

    /** Pages connected now (tests wait for theirs). */
    public int connectedPages() {
        return pages.size();
    }

    @Override
    public void close() {
        open = false;
        server.stop(0);
        threads.shutdownNow();
    }
}
