package org.miron.testkit.lsp;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.miron.lsp.server.MironLanguageServer;

/**
 * A real LSP client connected to an in-process MIRoN language server over piped streams: every
 * request and notification goes through LSP4J's JSON-RPC, as with an editor. Collects the
 * diagnostics the server publishes and waits for them.
 */
public final class LspClient implements LanguageClient, AutoCloseable {
    private static final long TIMEOUT_SECONDS = 60;

    private final Map<String, List<Diagnostic>> diagnostics = new ConcurrentHashMap<>();
    private final Map<String, Integer> versions = new ConcurrentHashMap<>();
    private final LanguageServer server;
    private final OutputStream toServer;

    /** A server in this JVM, on piped streams. */
    public LspClient() throws IOException {
        this(Pipes.toServerInThisJvm(), null, LanguageServer.class);
    }

    /** A server at the other end of the streams, e.g. a child process. */
    public LspClient(InputStream fromServer, OutputStream toServer) {
        this(new Pipes(fromServer, toServer), null, LanguageServer.class);
    }

    /**
     * A server in this JVM that speaks an extension of LSP, as an editor's extension does (e.g.
     * sprotty-vscode's {@code diagram/*} notifications): {@code extension} receives what the server
     * sends beyond LSP (its {@code @JsonNotification} methods), {@code remote} declares what the
     * client sends; {@link #server(Class)} gives the server as that interface.
     */
    public LspClient(Object extension, Class<? extends LanguageServer> remote) throws IOException {
        this(Pipes.toServerInThisJvm(), extension, remote);
    }

    @SuppressWarnings("unchecked")
    private LspClient(Pipes pipes, Object extension, Class<? extends LanguageServer> remote) {
        this.toServer = pipes.toServer;
        Launcher<LanguageServer> launcher = new Launcher.Builder<LanguageServer>()
                .setLocalServices(extension == null ? List.of(this) : List.of(this, extension))
                .setRemoteInterface((Class<LanguageServer>) remote).setClassLoader(remote.getClassLoader())
                .setInput(pipes.fromServer).setOutput(pipes.toServer).create();
        launcher.startListening();
        server = launcher.getRemoteProxy();
    }

    /** The two ends a client talks through. */
    private static final class Pipes {
        final InputStream fromServer;
        final OutputStream toServer;

        Pipes(InputStream fromServer, OutputStream toServer) {
            this.fromServer = fromServer;
            this.toServer = toServer;
        }

        static Pipes toServerInThisJvm() throws IOException {
            PipedInputStream serverIn = new PipedInputStream(1 << 16);
            PipedOutputStream toServer = new PipedOutputStream(serverIn);
            PipedInputStream clientIn = new PipedInputStream(1 << 16);
            PipedOutputStream serverOut = new PipedOutputStream(clientIn);
            MironLanguageServer.serve(serverIn, serverOut, false);
            return new Pipes(clientIn, toServer);
        }
    }

    /** A diagnostic's message as plain text. */
    public static String message(Diagnostic diagnostic) {
        return diagnostic.getMessage().isLeft() ? diagnostic.getMessage().getLeft()
                : diagnostic.getMessage().getRight().getValue();
    }

    public LanguageServer server() {
        return server;
    }

    /** The server as the extended interface it was connected with. */
    public <S extends LanguageServer> S server(Class<S> as) {
        return as.cast(server);
    }

    /** initialize + initialized with one workspace folder. */
    public InitializeResult initialize(Path workspace) throws Exception {
        return initialize(workspace, capabilities -> {
        });
    }

    /** initialize + initialized with one workspace folder and capabilities the test adjusts. */
    public InitializeResult initialize(Path workspace, java.util.function.Consumer<ClientCapabilities> adjust) throws Exception {
        InitializeParams params = new InitializeParams();
        WorkspaceClientCapabilities workspaceCapabilities = new WorkspaceClientCapabilities();
        workspaceCapabilities.setWorkspaceFolders(true);
        ClientCapabilities capabilities = new ClientCapabilities();
        capabilities.setWorkspace(workspaceCapabilities);
        adjust.accept(capabilities);
        params.setCapabilities(capabilities);
        params.setWorkspaceFolders(List.of(new WorkspaceFolder(uri(workspace), "workspace")));
        InitializeResult result = server.initialize(params).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());
        return result;
    }

    /** initialize + initialized as a client that opens single files, without any folder. */
    public void initializeWithoutWorkspace() throws Exception {
        server.initialize(new InitializeParams()).get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());
    }

    public static String uri(Path path) {
        return path.toAbsolutePath().normalize().toUri().toString();
    }

    public String open(Path file) throws IOException {
        return open(file, Files.readString(file));
    }

    public String open(Path file, String text) {
        String uri = uri(file);
        String name = file.getFileName().toString();
        String language = name.substring(name.lastIndexOf('.') + 1);
        versions.put(uri, 1);
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, language, 1, text)));
        return uri;
    }

    /** Replaces the whole unsaved buffer, as an editor may after a keystroke. */
    public void change(String uri, String text) {
        int version = versions.merge(uri, 1, Integer::sum);
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, version), List.of(new TextDocumentContentChangeEvent(text))));
    }

    /** The latest diagnostics for a file once they satisfy the condition. */
    public List<Diagnostic> awaitDiagnostics(String uri, Predicate<List<Diagnostic>> condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        synchronized (diagnostics) {
            while (true) {
                List<Diagnostic> current = diagnostics.get(uri);
                if (current != null && condition.test(current)) {
                    return current;
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new AssertionError("no matching diagnostics for " + uri + " within " + TIMEOUT_SECONDS
                            + " s; last: " + current);
                }
                diagnostics.wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
        }
    }

    /** What was last published for a file, or null. */
    public List<Diagnostic> published(String uri) {
        return diagnostics.get(uri);
    }

    /** Forgets what was published, so the next wait sees only new diagnostics. */
    public void forget(String uri) {
        synchronized (diagnostics) {
            diagnostics.remove(uri);
        }
    }

    @Override
    public void publishDiagnostics(PublishDiagnosticsParams params) {
        synchronized (diagnostics) {
            diagnostics.put(params.getUri(), params.getDiagnostics());
            diagnostics.notifyAll();
        }
    }

    @Override
    public void telemetryEvent(Object object) {
    }

    @Override
    public void showMessage(MessageParams params) {
    }

    @Override
    public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams params) {
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void logMessage(MessageParams params) {
    }

    /** The edits the server asked to apply (workspace/applyEdit), in order; all accepted. */
    public final List<org.eclipse.lsp4j.ApplyWorkspaceEditParams> appliedEdits = new java.util.concurrent.CopyOnWriteArrayList<>();

    @Override
    public CompletableFuture<org.eclipse.lsp4j.ApplyWorkspaceEditResponse> applyEdit(
            org.eclipse.lsp4j.ApplyWorkspaceEditParams params) {
        appliedEdits.add(params);
        synchronized (appliedEdits) {
            appliedEdits.notifyAll();
        }
        return CompletableFuture.completedFuture(new org.eclipse.lsp4j.ApplyWorkspaceEditResponse(true));
    }

    /** What the server registered dynamically (client/registerCapability), in order; all accepted. */
    public final List<org.eclipse.lsp4j.Registration> registrations = new java.util.concurrent.CopyOnWriteArrayList<>();

    @Override
    public CompletableFuture<Void> registerCapability(org.eclipse.lsp4j.RegistrationParams params) {
        synchronized (registrations) {
            registrations.addAll(params.getRegistrations());
            registrations.notifyAll();
        }
        return CompletableFuture.completedFuture(null);
    }

    /** The first registration of a method, once the server has sent it. */
    public org.eclipse.lsp4j.Registration awaitRegistration(String method) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(TIMEOUT_SECONDS);
        synchronized (registrations) {
            while (true) {
                for (org.eclipse.lsp4j.Registration registration : registrations) {
                    if (registration.getMethod().equals(method)) {
                        return registration;
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new AssertionError("no registration of " + method + " within " + TIMEOUT_SECONDS + " s");
                }
                registrations.wait(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            }
        }
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
