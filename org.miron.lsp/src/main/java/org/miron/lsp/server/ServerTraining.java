package org.miron.lsp.server;

import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;

/**
 * The training run of the server's AppCDS archive (`./miron lsp`, docs/lsp.md): an editor session
 * in one process, the server on piped streams, that opens a model, waits for its diagnostics and
 * asks for completion and hover, so the archive holds the classes a first file needs. Exits 0 once
 * the diagnostics arrived, 1 if they did not within a minute or anything failed (a missing model).
 */
public final class ServerTraining {
    private ServerTraining() {
    }

    public static void main(String[] args) {
        if (args.length != 1) {
            System.err.println("usage: ServerTraining MODEL.miron");
            System.exit(2);
        }
        int status;
        try {
            status = train(Path.of(args[0]).toAbsolutePath().normalize()) ? 0 : 1;
        } catch (Exception | Error e) {
            // Exit all the same: the server's threads would keep the JVM, and ./miron lsp, waiting.
            System.err.println("ServerTraining: " + e);
            status = 1;
        }
        System.exit(status);
    }

    private static boolean train(Path model) throws Exception {
        PipedInputStream serverIn = new PipedInputStream(1 << 16);
        PipedOutputStream toServer = new PipedOutputStream(serverIn);
        PipedInputStream clientIn = new PipedInputStream(1 << 16);
        MironLanguageServer.serve(serverIn, new PipedOutputStream(clientIn), false);
        String uri = model.toUri().toString();
        CountDownLatch diagnostics = new CountDownLatch(1);
        var launcher = LSPLauncher.createClientLauncher(new QuietClient(uri, diagnostics), clientIn, toServer);
        launcher.startListening();
        LanguageServer server = launcher.getRemoteProxy();
        InitializeParams params = new InitializeParams();
        params.setRootUri(model.getParent().toUri().toString());
        server.initialize(params).get(1, TimeUnit.MINUTES);
        server.initialized(new InitializedParams());
        String text = Files.readString(model);
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "miron", 1, text)));
        if (!diagnostics.await(1, TimeUnit.MINUTES)) {
            return false;
        }
        TextDocumentIdentifier document = new TextDocumentIdentifier(uri);
        Position middle = new Position(text.split("\n", -1).length / 2, 4);
        server.getTextDocumentService().completion(new CompletionParams(document, middle)).get(1, TimeUnit.MINUTES);
        server.getTextDocumentService().hover(new HoverParams(document, middle)).get(1, TimeUnit.MINUTES);
        server.shutdown().get(1, TimeUnit.MINUTES);
        return true;
    }

    /** A client that only waits for the model's diagnostics. */
    private static final class QuietClient implements LanguageClient {
        private final String uri;
        private final CountDownLatch diagnostics;

        QuietClient(String uri, CountDownLatch diagnostics) {
            this.uri = uri;
            this.diagnostics = diagnostics;
        }

        @Override
        public void publishDiagnostics(PublishDiagnosticsParams params) {
            if (params.getUri().equals(uri)) {
                diagnostics.countDown();
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
    }
}
