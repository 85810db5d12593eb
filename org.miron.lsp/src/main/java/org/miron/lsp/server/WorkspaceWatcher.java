package org.miron.lsp.server;

import static java.nio.file.StandardWatchEventKinds.ENTRY_CREATE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_DELETE;
import static java.nio.file.StandardWatchEventKinds.ENTRY_MODIFY;
import static java.nio.file.StandardWatchEventKinds.OVERFLOW;

import java.io.IOException;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.WatchEvent;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;

import org.eclipse.lsp4j.FileChangeType;
import org.eclipse.lsp4j.FileEvent;

/**
 * The server's own watch on the workspace folders, for clients that do not send
 * workspace/didChangeWatchedFiles (Neovim on Linux, some LSP4E set-ups): a model renamed,
 * edited or deleted on disk reaches the builder as if the client had sent the event, so the
 * files importing it are revalidated with every client. Java's WatchService watches single
 * folders: each one below a root is registered, except those the indexer skips, up to a bound.
 */
final class WorkspaceWatcher implements AutoCloseable {
    private static final Set<String> MODEL_EXTENSIONS = Set.of("bt", "roqme", "miron", "xml");
    private static final int MAX_FOLDERS = 5_000;

    private final WatchService service;
    private final Map<WatchKey, Path> folders = new ConcurrentHashMap<>();
    private final Consumer<List<FileEvent>> sink;
    private final Thread thread;

    WorkspaceWatcher(Consumer<List<FileEvent>> sink) throws IOException {
        this.sink = sink;
        this.service = FileSystems.getDefault().newWatchService();
        this.thread = new Thread(this::run, "miron-lsp-watcher");
        thread.setDaemon(true);
        thread.start();
    }

    /** Watches a folder and the folders below it (those the indexer reads). */
    void watch(Path root) {
        try {
            Files.walkFileTree(root, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) throws IOException {
                    if (!dir.equals(root) && BoundedFileSystemScanner.skipped(dir)) {
                        return FileVisitResult.SKIP_SUBTREE;
                    }
                    if (folders.size() >= MAX_FOLDERS) {
                        System.err.println("miron lsp: watching no more than " + MAX_FOLDERS
                                + " folders; changes on disk below " + dir + " are not seen");
                        return FileVisitResult.TERMINATE;
                    }
                    folders.put(dir.register(service, ENTRY_CREATE, ENTRY_DELETE, ENTRY_MODIFY), dir);
                    return FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult visitFileFailed(Path file, IOException exc) {
                    return FileVisitResult.CONTINUE;
                }
            });
        } catch (IOException | ClosedWatchServiceException e) {
            System.err.println("miron lsp: cannot watch " + root + ": " + e.getMessage());
        }
    }

    private void run() {
        try {
            while (true) {
                // One batch per burst: what a save or a move produced arrives as one build.
                Map<Path, FileChangeType> changes = new LinkedHashMap<>();
                WatchKey key = service.take();
                do {
                    collect(key, changes);
                    key = service.poll();
                } while (key != null);
                if (!changes.isEmpty()) {
                    List<FileEvent> events = new ArrayList<>();
                    changes.forEach((file, type) -> events.add(new FileEvent(file.toUri().toString(), type)));
                    sink.accept(events);
                }
            }
        } catch (InterruptedException | ClosedWatchServiceException stopped) {
            // close()
        } catch (RuntimeException e) {
            System.err.println("miron lsp: the workspace watcher stopped: " + e);
        }
    }

    private void collect(WatchKey key, Map<Path, FileChangeType> changes) {
        Path dir = folders.get(key);
        for (WatchEvent<?> event : key.pollEvents()) {
            if (dir == null || event.kind() == OVERFLOW) {
                continue;
            }
            Path path = dir.resolve((Path) event.context());
            if (event.kind() == ENTRY_CREATE && Files.isDirectory(path) && !BoundedFileSystemScanner.skipped(path)) {
                watch(path);
                announceFilesBelow(path, changes);
            } else if (isModel(path)) {
                FileChangeType type = event.kind() == ENTRY_CREATE ? FileChangeType.Created
                        : event.kind() == ENTRY_DELETE ? FileChangeType.Deleted : FileChangeType.Changed;
                // A file created then modified in one burst is still new; deleted then created, changed.
                changes.merge(path, type, (before, after) -> before == FileChangeType.Created
                        && after == FileChangeType.Changed ? before
                        : before == FileChangeType.Deleted && after == FileChangeType.Created ? FileChangeType.Changed : after);
            }
        }
        if (!key.reset()) {
            folders.remove(key);
        }
    }

    /** A folder moved in brings its models with it: the watch sees only the folder's creation. */
    private void announceFilesBelow(Path folder, Map<Path, FileChangeType> changes) {
        try (var files = Files.walk(folder)) {
            files.filter(WorkspaceWatcher::isModel).filter(Files::isRegularFile)
                    .forEach(file -> changes.put(file, FileChangeType.Created));
        } catch (IOException | java.io.UncheckedIOException e) {
            // Gone again: nothing to announce.
        }
    }

    private static boolean isModel(Path path) {
        String name = path.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 && MODEL_EXTENSIONS.contains(name.substring(dot + 1));
    }

    @Override
    public void close() {
        try {
            service.close();
        } catch (IOException e) {
            // Closing a watch service only releases its handles.
        }
        thread.interrupt();
    }
}
