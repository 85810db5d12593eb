package org.miron.cli.monitor;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.miron.runtime.Json;
import org.miron.runtime.groot.GrootConnection.Position;

import com.fasterxml.jackson.databind.JsonNode;
import com.sun.net.httpserver.HttpExchange;

/**
 * The page's debugging requests, {@code /debug/...}: GET {@code state}; POST {@code breakpoint}
 * ({@code {"node","position":"PRE|POST","once"}}), {@code force} ({@code {"node","status","once"}}),
 * {@code clear} ({@code {"node"}}), {@code continue}, {@code step}, {@code clear-all}. Each answers
 * the debugger's state as JSON, or an HTTP error whose body is the message the page shows
 * (400 bad request, 404 unknown node, 409 not now, 503 no Groot2 server).
 */
final class DebugRoutes {
    private static final int MAX_BODY = 4096;

    private final MonitorDebugger debugger;

    /** {@code debugger}: null when the monitor was given no Groot2 server to attach to. */
    DebugRoutes(MonitorDebugger debugger) {
        this.debugger = debugger;
    }

    void handle(HttpExchange exchange) throws IOException {
        String action = exchange.getRequestURI().getPath().substring("/debug/".length());
        try {
            if (debugger == null) {
                throw new MonitorDebugger.Refused(503, "no Groot2 server to debug with: start the executor with --groot PORT");
            }
            debugger.asked();
            boolean post = exchange.getRequestMethod().equals("POST");
            if (action.equals("state") && !post) {
                reply(exchange, 200, debugger.state().toString());
                return;
            }
            if (!post) {
                throw new MonitorDebugger.Refused(405, "POST /debug/" + action);
            }
            JsonNode body = body(exchange);
            switch (action) {
            case "breakpoint" -> debugger.breakpoint(text(body, "node"), position(body), body.path("once").asBoolean(false));
            case "force" -> debugger.force(text(body, "node"), text(body, "status"), body.path("once").asBoolean(false));
            case "clear" -> debugger.clear(text(body, "node"));
            case "continue" -> debugger.resume();
            case "step" -> debugger.step();
            case "clear-all" -> debugger.clearAll();
            default -> throw new MonitorDebugger.Refused(404, "no such request: /debug/" + action);
            }
            reply(exchange, 200, debugger.state().toString());
        } catch (MonitorDebugger.Refused refused) {
            reply(exchange, refused.status, refused.getMessage());
        }
    }

    private static JsonNode body(HttpExchange exchange) throws IOException, MonitorDebugger.Refused {
        byte[] bytes;
        try (InputStream in = exchange.getRequestBody()) {
            bytes = in.readNBytes(MAX_BODY + 1);
        }
        if (bytes.length > MAX_BODY) {
            throw new MonitorDebugger.Refused(400, "a request body has at most " + MAX_BODY + " bytes");
        }
        if (bytes.length == 0) {
            return Json.MAPPER.createObjectNode();
        }
        try {
            JsonNode json = Json.MAPPER.readTree(bytes);
            if (json == null || !json.isObject()) {
                throw new MonitorDebugger.Refused(400, "the request body is a JSON object");
            }
            return json;
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new MonitorDebugger.Refused(400, "the request body is not JSON: " + e.getOriginalMessage());
        }
    }

    private static String text(JsonNode body, String field) throws MonitorDebugger.Refused {
        JsonNode value = body.get(field);
        if (value == null || !value.isTextual()) {
            throw new MonitorDebugger.Refused(400, "\"" + field + "\" is missing (a string)");
        }
        return value.textValue();
    }

    private static Position position(JsonNode body) throws MonitorDebugger.Refused {
        String position = body.path("position").asText("PRE");
        try {
            return Position.valueOf(position);
        } catch (IllegalArgumentException e) {
            throw new MonitorDebugger.Refused(400, "\"position\" is PRE or POST, not " + position);
        }
    }

    private static void reply(HttpExchange exchange, int code, String body) throws IOException {
        HttpReplies.reply(exchange, code, code == 200 ? "application/json" : "text/plain; charset=utf-8",
                body.getBytes(StandardCharsets.UTF_8));
    }
}
