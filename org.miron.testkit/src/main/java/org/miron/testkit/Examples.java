package org.miron.testkit;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Temporary copies of the repository's examples (examples/NAME), so tests can edit and delete files. */
public final class Examples {
    private Examples() {
    }

    /** A copy of examples/NAME in a new temporary folder (Folders.delete removes it). */
    public static Path copy(String name) throws IOException {
        return Folders.copy(RepositoryRoot.resolve("examples").resolve(name), Files.createTempDirectory("miron-" + name));
    }
}
