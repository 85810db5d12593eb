package org.miron.testkit;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/** Temporary copies of the repository's examples (examples/NAME), so tests can edit and delete files. */
public final class Examples {
    private Examples() {
    }

    /** A copy of examples/NAME in a new temporary folder. */
    public static Path copy(String name) throws IOException {
        Path source = RepositoryRoot.resolve("examples").resolve(name);
        Path target = Files.createTempDirectory("miron-" + name);
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

    /** Deletes a folder and everything in it. */
    public static void delete(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted((a, b) -> b.getNameCount() - a.getNameCount()).forEach(file -> file.toFile().delete());
        }
    }
}
