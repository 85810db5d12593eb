package org.miron.lsp.server;

import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * The folders the server may index, from what a client sends: only absolute file URIs (or paths)
 * of existing folders other than the file-system root. Neovim's documented {@code
 * vim.fs.dirname(args.file)} of a relative file name sends {@code file://.}, which Xtext read as
 * "/" and scanned the whole disk; such a root is refused and the opened files' folders serve.
 */
public final class WorkspaceRoots {

    private WorkspaceRoots() {
    }

    /** The folder a workspace URI names, or empty (with the reason logged) if it is not usable. */
    public static Optional<Path> folder(String uri) {
        Optional<Path> folder = parse(uri).filter(Files::isDirectory).filter(path -> path.getParent() != null);
        if (folder.isEmpty()) {
            System.err.println("miron lsp: ignoring workspace folder '" + uri
                    + "': not an absolute file URI of a folder below '/'; the opened files' folders are used instead");
        }
        return folder;
    }

    /** A root path (the deprecated rootPath) as a folder, or empty if it is not absolute. */
    public static Optional<Path> folderOfPath(String path) {
        try {
            Path folder = Path.of(path);
            return folder.isAbsolute() ? folder(folder.toUri().toString()) : folder("file:" + path);
        } catch (InvalidPathException e) {
            return folder("file:" + path);
        }
    }

    /** The folder of a document, or empty for a document that is not an absolute file URI. */
    public static Optional<Path> folderOfDocument(String uri) {
        return parse(uri).map(Path::getParent).filter(Files::isDirectory).filter(path -> path.getParent() != null);
    }

    private static Optional<Path> parse(String uri) {
        if (uri == null) {
            return Optional.empty();
        }
        try {
            URI parsed = new URI(uri);
            String authority = parsed.getRawAuthority();
            boolean local = authority == null || authority.isEmpty() || authority.equals("localhost");
            if (!"file".equalsIgnoreCase(parsed.getScheme()) || !local || parsed.getPath() == null
                    || !parsed.getPath().startsWith("/")) {
                return Optional.empty();
            }
            return Optional.of(Path.of(new URI("file", null, parsed.getPath(), null)).normalize());
        } catch (URISyntaxException | IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    /** The URI string the server uses for a folder (file:///..., with a trailing slash). */
    public static String uri(Path folder) {
        return folder.toUri().toString();
    }
}
