package org.miron.lsp.server;

import java.io.IOException;
import java.util.ArrayList;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;

import org.eclipse.lsp4j.DidChangeWatchedFilesCapabilities;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesRegistrationOptions;
import org.eclipse.lsp4j.FileEvent;
import org.eclipse.lsp4j.FileSystemWatcher;
import org.eclipse.lsp4j.Registration;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Where the server learns of changes on disk: a client that can watch files is asked to
 * (client/registerCapability of workspace/didChangeWatchedFiles for the model files); with any
 * other client, or if the registration fails, the server watches its folders itself
 * ({@link WorkspaceWatcher}), from initialize on.
 */
final class FileChangeSource implements AutoCloseable {
    static final String GLOB = "**/*.{bt,roqme,miron,xml}";

    private final Consumer<DidChangeWatchedFilesParams> server;
    private boolean clientCanWatch;
    private WorkspaceWatcher watcher;
    private boolean closed;
    /** Changes seen before the workspace's first build is under way; null once they are passed on. */
    private List<FileEvent> early = new ArrayList<>();

    FileChangeSource(Consumer<DidChangeWatchedFilesParams> server) {
        this.server = server;
    }

    /**
     * In initialize: whether the client will watch; if not, the server's watch starts now, before
     * the workspace is built, so that nothing changed on disk during the first build goes unseen
     * (its events wait for {@link #start}).
     */
    void initialize(DidChangeWatchedFilesCapabilities capabilities, List<Path> folders) {
        clientCanWatch = capabilities != null && Boolean.TRUE.equals(capabilities.getDynamicRegistration());
        if (!clientCanWatch) {
            watchAll(folders);
        }
    }

    /** After initialized: the client is asked to watch if it can; the server's early events are passed on. */
    void start(LanguageClient client, List<Path> folders) {
        if (!clientCanWatch) {
            passOn();
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
                passOn();
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
            watcher = new WorkspaceWatcher(this::changed);
            folders.forEach(watcher::watch);
        } catch (IOException e) {
            System.err.println("miron lsp: cannot watch the workspace (" + e.getMessage()
                    + "): changes on disk are seen only if the editor reports them");
        }
    }

    private void changed(List<FileEvent> events) {
        synchronized (this) {
            if (early != null) {
                early.addAll(events);
                return;
            }
        }
        server.accept(new DidChangeWatchedFilesParams(events));
    }

    private void passOn() {
        List<FileEvent> events;
        synchronized (this) {
            events = early;
            early = null;
        }
        if (events != null && !events.isEmpty()) {
            server.accept(new DidChangeWatchedFilesParams(events));
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
