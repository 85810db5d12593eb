package org.miron.lsp.diagram;

import java.lang.System.Logger.Level;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import java.util.Set;
import java.util.function.BiFunction;
import java.util.function.UnaryOperator;

import org.eclipse.sprotty.ActionMessage;
import org.eclipse.sprotty.OpenAction;
import org.eclipse.sprotty.SelectAction;
import org.miron.diagram.SourceSpan;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * The diagram clients of one language-server connection, by client id: what arrives on
 * {@code diagram/accept} goes to the client's server (made on its first message), what the servers
 * send goes out on {@code diagram/accept}, and opening or selecting a node reveals its source
 * ({@code diagram/openInTextEditor}, which sprotty-vscode handles).
 */
public final class DiagramServers {
    private static final System.Logger LOG = System.getLogger(DiagramServers.class.getName());
    /** Long enough for the refresh that follows an edit's write to have been asked for. */
    private static final Executor ASK_AGAIN = CompletableFuture.delayedExecutor(100, TimeUnit.MILLISECONDS);
    private final Map<String, MironDiagramServer> servers = new ConcurrentHashMap<>();
    private final BiFunction<String, Set<String>, CompletableFuture<DiagramGeneration.Generated>> generate;
    /** A resource's URI as the client writes it (file:///...). */
    private final UnaryOperator<String> clientUri;
    private volatile BiConsumer<String, Object> notifier = (method, params) -> {
    };

    /**
     * @param generate the diagram of a file (its URI) with the given SubTree calls expanded, read
     *        after the writes queued before it
     * @param clientUri a resource's URI as the client writes it
     */
    public DiagramServers(BiFunction<String, Set<String>, CompletableFuture<DiagramGeneration.Generated>> generate,
            UnaryOperator<String> clientUri) {
        this.generate = generate;
        this.clientUri = clientUri;
    }

    /** Where notifications to the client go (the JSON-RPC endpoint of the connection). */
    public void connect(BiConsumer<String, Object> notifier) {
        this.notifier = notifier;
    }

    public void accept(JsonElement json) {
        ActionMessage message = DiagramJson.read(json);
        if (message == null || message.getClientId() == null) {
            return;
        }
        servers.computeIfAbsent(message.getClientId(), this::create).accept(message);
    }

    public void didClose(String clientId) {
        if (clientId != null) {
            servers.remove(clientId);
        }
    }

    /** Every open diagram made again, after an edit (a file a diagram includes may have changed too). */
    public void refreshAll() {
        servers.values().forEach(this::refresh);
    }

    /** Waits for every diagram's latest model (tests and benchmarks). */
    public CompletableFuture<Void> refreshAllAndWait() {
        return CompletableFuture.allOf(servers.values().stream().map(this::refresh).toArray(CompletableFuture[]::new));
    }

    // Models are read in parallel and an edit cancels the reads before it: only the model of the
    // latest read is shown, whichever read ends first (the server checks, under its lock).
    private CompletableFuture<?> refresh(MironDiagramServer server) {
        MironDiagramServer.Read read = server.nextRead();
        if (read == null) {
            return CompletableFuture.completedFuture(null);
        }
        String file = read.uri().substring(read.uri().lastIndexOf('/') + 1);
        return generate.apply(read.uri(), read.expandedCalls()).handle((generated, failure) -> {
            if (failure instanceof CancellationException
                    || failure != null && failure.getCause() instanceof CancellationException) {
                // A write cancelled the read. An edit asks again itself (refreshAll); after a
                // write that builds nothing, the latest read is made again, so that a client
                // never waits for its model for ever.
                ASK_AGAIN.execute(() -> {
                    if (server.isLatest(read.number())) {
                        refresh(server);
                    }
                });
            } else if (failure != null) {
                LOG.log(Level.WARNING, "no diagram of " + read.uri(), failure);
                server.fail(read.number(), file + ": no diagram (" + reason(failure) + ")");
            } else {
                server.show(read.number(), generated, file);
            }
            return null;
        });
    }

    private static String reason(Throwable failure) {
        Throwable cause = failure instanceof CompletionException && failure.getCause() != null ? failure.getCause() : failure;
        return cause.getMessage() != null ? cause.getMessage() : cause.getClass().getSimpleName();
    }

    private MironDiagramServer create(String clientId) {
        MironDiagramServer server = new MironDiagramServer(clientId, this::refresh);
        server.setRemoteEndpoint(message -> notifier.accept("diagram/accept", DiagramJson.write(message)));
        server.setOpenListener((action, from) -> reveal(server, ((OpenAction) action).getElementId(), true));
        server.setSelectionListener((action, from) -> {
            if (action instanceof SelectAction select && select.getSelectedElementsIDs() != null
                    && select.getSelectedElementsIDs().size() == 1) {
                reveal(server, select.getSelectedElementsIDs().get(0), false);
            }
        });
        server.setExpansionListener((action, from) -> refresh(server));
        return server;
    }

    private void reveal(MironDiagramServer server, String elementId, boolean forceOpen) {
        SourceSpan span = elementId == null ? null : server.span(elementId);
        if (span != null) {
            notifier.accept("diagram/openInTextEditor", openInTextEditor(span, clientUri.apply(span.uri()), forceOpen));
        }
    }

    /** sprotty-vscode's OpenInTextEditorMessage: {location: {uri, range}, forceOpen}. */
    static JsonObject openInTextEditor(SourceSpan span, String uri, boolean forceOpen) {
        JsonObject range = new JsonObject();
        range.add("start", position(span.startLine(), span.startCharacter()));
        range.add("end", position(span.endLine(), span.endCharacter()));
        JsonObject location = new JsonObject();
        location.addProperty("uri", uri);
        location.add("range", range);
        JsonObject message = new JsonObject();
        message.add("location", location);
        message.addProperty("forceOpen", forceOpen);
        return message;
    }

    private static JsonObject position(int line, int character) {
        JsonObject position = new JsonObject();
        position.addProperty("line", line);
        position.addProperty("character", character);
        return position;
    }
}
