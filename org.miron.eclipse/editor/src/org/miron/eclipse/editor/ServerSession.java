package org.miron.eclipse.editor;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.Pipe;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Future;

import org.miron.lsp.server.MironLanguageServer;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * A short client session with an in-process MIRoN language server (JSON-RPC over LSP's base
 * protocol on NIO pipes): initialize on a folder, then requests, then shutdown and exit.
 */
final class ServerSession implements AutoCloseable {
    private final OutputStream toServer;
    private final InputStream fromServer;
    private final Future<Void> listening;
    private int nextId = 1;

    ServerSession(Path root) throws IOException {
        Pipe clientToServer = Pipe.open();
        Pipe serverToClient = Pipe.open();
        toServer = Channels.newOutputStream(clientToServer.sink());
        fromServer = Channels.newInputStream(serverToClient.source());
        listening = MironLanguageServer.serve(Channels.newInputStream(clientToServer.source()),
                Channels.newOutputStream(serverToClient.sink()), false);
        JsonObject params = new JsonObject();
        params.add("processId", null);
        params.addProperty("rootUri", root.toUri().toString());
        params.add("capabilities", new JsonObject());
        request("initialize", params);
        notify("initialized", new JsonObject());
    }

    /**
     * workspace/executeCommand miron.generate on the model: the server's answer ({ok, message,
     * written, errors}).
     */
    JsonObject generate(Path model) throws IOException {
        JsonObject params = new JsonObject();
        params.addProperty("command", "miron.generate");
        JsonArray arguments = new JsonArray();
        arguments.add(model.toUri().toString());
        params.add("arguments", arguments);
        JsonObject response = request("workspace/executeCommand", params);
        if (response.has("error")) {
            throw new IOException("miron.generate: " + response.get("error"));
        }
        return response.getAsJsonObject("result");
    }

    JsonObject request(String method, JsonObject params) throws IOException {
        int id = nextId++;
        JsonObject message = new JsonObject();
        message.addProperty("jsonrpc", "2.0");
        message.addProperty("id", id);
        message.addProperty("method", method);
        message.add("params", params);
        send(message);
        while (true) {
            JsonObject answer = JsonParser.parseString(read()).getAsJsonObject();
            if (answer.has("id") && !answer.has("method") && answer.get("id").getAsInt() == id) {
                return answer;
            }
        }
    }

    private void notify(String method, JsonObject params) throws IOException {
        JsonObject message = new JsonObject();
        message.addProperty("jsonrpc", "2.0");
        message.addProperty("method", method);
        message.add("params", params);
        send(message);
    }

    private void send(JsonObject message) throws IOException {
        byte[] body = message.toString().getBytes(StandardCharsets.UTF_8);
        toServer.write(("Content-Length: " + body.length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
        toServer.write(body);
        toServer.flush();
    }

    private String read() throws IOException {
        int length = -1;
        StringBuilder line = new StringBuilder();
        while (true) {
            int c = fromServer.read();
            if (c < 0) {
                throw new EOFException("the MIRoN language server closed the connection");
            }
            if (c == '\n') {
                String header = line.toString().trim();
                if (header.isEmpty()) {
                    break;
                }
                if (header.toLowerCase().startsWith("content-length:")) {
                    length = Integer.parseInt(header.substring("content-length:".length()).trim());
                }
                line.setLength(0);
            } else {
                line.append((char) c);
            }
        }
        return new String(fromServer.readNBytes(length), StandardCharsets.UTF_8);
    }

    @Override
    public void close() {
        try {
            request("shutdown", new JsonObject());
            notify("exit", new JsonObject());
        } catch (IOException e) {
            // The server is going away anyway.
        }
        try {
            toServer.close();
            fromServer.close();
        } catch (IOException e) {
            // Closing pipes: nothing to report.
        }
        listening.cancel(true);
    }
}
