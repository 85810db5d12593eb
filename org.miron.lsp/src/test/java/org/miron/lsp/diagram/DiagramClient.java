package org.miron.lsp.diagram;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.services.JsonNotification;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.miron.lsp.server.MironLanguageServer;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * An LSP client that is also a diagram client, as sprotty-vscode's extension is: it sends Sprotty
 * actions on {@code diagram/accept} and records what the server sends back (actions, and the
 * {@code diagram/openInTextEditor} reveals), over LSP4J's JSON-RPC to an in-process server.
 */
public final class DiagramClient implements LanguageClient, AutoCloseable {
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

    private final List<Received> received = new ArrayList<>();
    private final DiagramLanguageServer server;
    private final OutputStream toServer;
    private int version = 1;

    public DiagramClient() throws IOException {
        PipedInputStream serverIn = new PipedInputStream(1 << 16);
        toServer = new PipedOutputStream(serverIn);
        PipedInputStream clientIn = new PipedInputStream(1 << 16);
        PipedOutputStream serverOut = new PipedOutputStream(clientIn);
        MironLanguageServer.serve(serverIn, serverOut, false);
        Launcher<DiagramLanguageServer> launcher = Launcher.createLauncher(this, DiagramLanguageServer.class, clientIn,
                toServer);
        launcher.startListening();
        server = launcher.getRemoteProxy();
    }

    public DiagramLanguageServer server() {
        return server;
    }

    public void initialize(Path workspace) throws Exception {
        InitializeParams params = new InitializeParams();
        params.setWorkspaceFolders(List.of(new WorkspaceFolder(workspace.toUri().toString(), "workspace")));
        server.initialize(params).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());
    }

    public String open(Path file, String text, String language) {
        String uri = file.toAbsolutePath().normalize().toUri().toString();
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, language, 1, text)));
        return uri;
    }

    public void change(String uri, String text) {
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, ++version), List.of(new TextDocumentContentChangeEvent(text))));
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

    @JsonNotification("diagram/accept")
    public void diagramAccept(JsonObject message) {
        record("diagram/accept", message);
    }

    @JsonNotification("diagram/openInTextEditor")
    public void openInTextEditor(JsonObject message) {
        record("diagram/openInTextEditor", message);
    }

    private void record(String method, JsonElement params) {
        synchronized (received) {
            received.add(new Received(method, params.getAsJsonObject()));
            received.notifyAll();
        }
    }

    @Override
    public void telemetryEvent(Object object) {
    }

    @Override
    public void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
    }

    @Override
    public void showMessage(MessageParams messageParams) {
    }

    @Override
    public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams requestParams) {
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void logMessage(MessageParams message) {
    }

    @Override
    public CompletableFuture<Void> registerCapability(RegistrationParams params) {
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void close() throws Exception {
        try {
            server.shutdown().get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
            server.exit();
        } finally {
            toServer.close();
        }
    }
}
