package org.miron.lsp.server;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/** Temporary copies of the repository's examples, so tests can edit and delete files. */
public final class Workspaces {
    private Workspaces() {
    }

    public static Path root() {
        return Path.of(System.getProperty("miron.root", "..")).toAbsolutePath().normalize();
    }

    public static Path copyOfExample(String name) throws IOException {
        Path source = root().resolve("examples").resolve(name);
        Path target = Files.createTempDirectory("miron-lsp-" + name);
        try (Stream<Path> files = Files.walk(source)) {
            files.forEach(file -> {
                try {
                    Path copy = target.resolve(source.relativize(file).toString());
                    if (Files.isDirectory(file)) {
                        Files.createDirectories(copy);
                    } else {
                        Files.copy(file, copy);
                    }
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        }
        return target;
    }

    public static void delete(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted((a, b) -> b.getNameCount() - a.getNameCount()).forEach(file -> file.toFile().delete());
        }
    }
}
