package org.miron.cli.monitor;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

import com.sun.net.httpserver.HttpExchange;

/** The monitor's HTTP answers (live page, replay, debug routes): never cached, the page only at "/". */
final class HttpReplies {
    private HttpReplies() {
    }

    static void reply(HttpExchange exchange, int code, String type, byte[] body) throws IOException {
        exchange.getResponseHeaders().set("Content-Type", type);
        exchange.getResponseHeaders().set("Cache-Control", "no-store");
        exchange.sendResponseHeaders(code, body.length);
        try (OutputStream out = exchange.getResponseBody()) {
            out.write(body);
        }
    }

    /** The page at "/", 404 for any other path of its context. */
    static void page(HttpExchange exchange, byte[] page) throws IOException {
        if (!exchange.getRequestURI().getPath().equals("/")) {
            reply(exchange, 404, "text/plain", "not found\n".getBytes(StandardCharsets.UTF_8));
            return;
        }
        reply(exchange, 200, "text/html; charset=utf-8", page);
    }
}
