package org.miron.lsp.diagram;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.eclipse.lsp4j.jsonrpc.services.JsonNotification;
import org.eclipse.lsp4j.services.LanguageServer;
import org.miron.testkit.lsp.LspClient;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * An LSP client that is also a diagram client, as sprotty-vscode's extension is: the test kit's
 * {@link LspClient} extended with the diagram notifications. It sends Sprotty actions on
 * {@code diagram/accept} and records what the server sends back (actions, and the
 * {@code diagram/openInTextEditor} reveals).
 */
public final class DiagramClient implements AutoCloseable {
    static final long TIMEOUT_SECONDS = 60;

    /** The server as sprotty-vscode's extension sees it: LSP plus the diagram notifications. */
    public interface DiagramLanguageServer extends LanguageServer {
        @JsonNotification("diagram/accept")
        void accept(JsonObject message);

        @JsonNotification("diagram/didClose")
        void didClose(String clientId);
    }

    /** One notification from the server: its method and parameters. */
    // A class, not a record: Gradle 4.4.1's test scanner cannot read records.
    public static final class Received {
        private final String method;
        private final JsonObject params;

        Received(String method, JsonObject params) {
            this.method = method;
            this.params = params;
        }

        String method() {
            return method;
        }

        JsonObject params() {
            return params;
        }

        @Override
        public String toString() {
            return method + " " + params;
        }

        String kind() {
            return params.has("action") ? params.getAsJsonObject("action").get("kind").getAsString() : null;
        }

        JsonObject action() {
            return params.getAsJsonObject("action");
        }
    }

    /** What the server sends on the diagram protocol (an LSP4J local service beside the client's). */
    public final class Notifications {
        @JsonNotification("diagram/accept")
        public void diagramAccept(JsonObject message) {
            record("diagram/accept", message);
        }

        @JsonNotification("diagram/openInTextEditor")
        public void openInTextEditor(JsonObject message) {
            record("diagram/openInTextEditor", message);
        }
    }

    private final List<Received> received = new ArrayList<>();
    private final LspClient lsp;
    private final DiagramLanguageServer server;

    public DiagramClient() throws IOException {
        lsp = new LspClient(new Notifications(), DiagramLanguageServer.class);
        server = lsp.server(DiagramLanguageServer.class);
    }

    public DiagramLanguageServer server() {
        return server;
    }

    public void initialize(Path workspace) throws Exception {
        lsp.initialize(workspace);
    }

    public String open(Path file, String text) {
        return lsp.open(file, text);
    }

    public void change(String uri, String text) {
        lsp.change(uri, text);
    }

    /** Sends an action (its JSON) from a diagram client. */
    public void send(String clientId, JsonObject action) {
        JsonObject message = new JsonObject();
        message.addProperty("clientId", clientId);
        message.add("action", action);
        server.accept(message);
    }

    /** How many notifications have arrived: {@link #await} looks at those after a mark. */
    public int mark() {
        synchronized (received) {
            return received.size();
        }
    }

    /** The first notification from index {@code from} on that matches, waiting for it. */
    public Received await(int from, Predicate<Received> condition, String what) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        synchronized (received) {
            while (true) {
                for (int i = from; i < received.size(); i++) {
                    if (condition.test(received.get(i))) {
                        return received.get(i);
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new AssertionError("no " + what + " within " + TIMEOUT_SECONDS + " s; received: " + received);
                }
                received.wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
        }
    }

    /** The notifications received from index {@code from} to {@code to}. */
    public List<Received> between(int from, int to) {
        synchronized (received) {
            return new ArrayList<>(received.subList(from, to));
        }
    }

    public int indexOf(Received notification) {
        synchronized (received) {
            return received.indexOf(notification);
        }
    }

    private void record(String method, JsonElement params) {
        synchronized (received) {
            received.add(new Received(method, params.getAsJsonObject()));
            received.notifyAll();
        }
    }

    @Override
    public void close() throws Exception {
        lsp.close();
    }
}
