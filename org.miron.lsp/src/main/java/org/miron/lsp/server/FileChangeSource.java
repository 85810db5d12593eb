package org.miron.lsp.server;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;

import org.eclipse.lsp4j.DidChangeWatchedFilesCapabilities;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesRegistrationOptions;
import org.eclipse.lsp4j.FileSystemWatcher;
import org.eclipse.lsp4j.Registration;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Where the server learns of changes on disk: a client that can watch files is asked to
 * (client/registerCapability of workspace/didChangeWatchedFiles for the model files); with any
 * other client, or if the registration fails, the server watches its folders itself
 * ({@link WorkspaceWatcher}).
 */
final class FileChangeSource implements AutoCloseable {
    static final String GLOB = "**/*.{bt,roqme,miron,xml}";

    private final Consumer<DidChangeWatchedFilesParams> server;
    private boolean clientCanWatch;
    private WorkspaceWatcher watcher;
    private boolean closed;

    FileChangeSource(Consumer<DidChangeWatchedFilesParams> server) {
        this.server = server;
    }

    void clientCanWatch(DidChangeWatchedFilesCapabilities capabilities) {
        clientCanWatch = capabilities != null && Boolean.TRUE.equals(capabilities.getDynamicRegistration());
    }

    /** After initialized: the client's watch if it offers one, else the server's own on the folders. */
    void start(LanguageClient client, List<Path> folders) {
        if (!clientCanWatch) {
            watchAll(folders);
            return;
        }
        FileSystemWatcher models = new FileSystemWatcher(Either.forLeft(GLOB));
        Registration registration = new Registration("miron-watched-files", "workspace/didChangeWatchedFiles",
                new DidChangeWatchedFilesRegistrationOptions(List.of(models)));
        client.registerCapability(new RegistrationParams(List.of(registration))).whenComplete((ok, failed) -> {
            if (failed != null) {
                System.err.println("miron lsp: the client refused to watch files (" + failed.getMessage()
                        + "); the server watches the workspace itself");
                watchAll(folders);
            }
        });
    }

    /** A folder added to the workspace later, watched if the server is the one watching. */
    synchronized void watch(Path folder) {
        if (watcher != null) {
            watcher.watch(folder);
        }
    }

    private synchronized void watchAll(List<Path> folders) {
        if (closed) {
            return;
        }
        try {
            watcher = new WorkspaceWatcher(events -> server.accept(new DidChangeWatchedFilesParams(events)));
            folders.forEach(watcher::watch);
        } catch (IOException e) {
            System.err.println("miron lsp: cannot watch the workspace (" + e.getMessage()
                    + "): changes on disk are seen only if the editor reports them");
        }
    }

    @Override
    public synchronized void close() {
        closed = true;
        if (watcher != null) {
            watcher.close();
            watcher = null;
        }
    }
}
