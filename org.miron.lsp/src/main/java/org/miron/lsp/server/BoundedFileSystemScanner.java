package org.miron.lsp.server;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.util.IAcceptor;
import org.eclipse.xtext.util.IFileSystemScanner;
import org.eclipse.xtext.util.UriExtensions;

/**
 * The files of a workspace folder the server indexes: Xtext's scanner walked every folder below
 * the root, however big. This one skips hidden folders, build outputs and node_modules, follows
 * no symbolic links, and stops (saying so on standard error) after a bounded number of entries,
 * so a folder opened by mistake (a home directory) costs seconds, not the machine.
 */
public class BoundedFileSystemScanner implements IFileSystemScanner {
    /** Folders never indexed: build outputs and package caches hold copies, not the user's models. */
    public static final Set<String> SKIPPED = Set.of("build", "node_modules", "target");
    private static final int DEFAULT_LIMIT = 20_000;

    private final int limit;
    // The URI form Xtext gives open documents (file:///...), so scanned files and open ones match.
    private final UriExtensions uris = new UriExtensions();

    public BoundedFileSystemScanner() {
        this(Integer.getInteger("miron.lsp.scanLimit", DEFAULT_LIMIT));
    }

    public BoundedFileSystemScanner(int limit) {
        this.limit = limit;
    }

    /** Whether a folder below a workspace root is left out of indexing and watching. */
    public static boolean skipped(Path folder) {
        String name = folder.getFileName() == null ? "" : folder.getFileName().toString();
        return name.startsWith(".") || SKIPPED.contains(name);
    }

    @Override
    public void scan(URI root, IAcceptor<URI> acceptor) {
        if (!root.isFile()) {
            return;
        }
        Path start = Path.of(root.toFileString());
        if (!Files.isDirectory(start)) {
            return;
        }
        int[] seen = { 0 };
        try {
            Files.walkFileTree(start, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                    if (!dir.equals(start) && skipped(dir)) {
                        return FileVisitResult.SKIP_SUBTREE;
                    }
                    return count();
                }

                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                    if (attrs.isRegularFile()) {
                        acceptor.accept(uris.toEmfUri(file.toAbsolutePath().toUri()));
                    }
                    return count();
                }

                @Override
                public FileVisitResult visitFileFailed(Path file, IOException exc) {
                    return FileVisitResult.CONTINUE;
                }

                private FileVisitResult count() {
                    if (++seen[0] < limit) {
                        return FileVisitResult.CONTINUE;
                    }
                    System.err.println("miron lsp: stopped indexing " + start + " after " + limit
                            + " files and folders: open the models' own folder as the workspace");
                    return FileVisitResult.TERMINATE;
                }
            });
        } catch (IOException e) {
            System.err.println("miron lsp: cannot index " + start + ": " + e.getMessage());
        }
    }
}
