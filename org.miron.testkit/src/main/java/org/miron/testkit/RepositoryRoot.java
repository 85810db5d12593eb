package org.miron.testkit;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The repository root, found one way for every test: the {@code miron.root} system property, which
 * the build sets for every test task (gradle/java-conventions.gradle); else, for a test run from an
 * IDE, the nearest folder above the working directory holding settings.gradle.
 */
public final class RepositoryRoot {
    private static Path root;

    private RepositoryRoot() {
    }

    /** The root, absolute and normalised; an IllegalStateException saying why when there is none. */
    public static synchronized Path path() {
        if (root == null) {
            root = find();
        }
        return root;
    }

    /** A path below the root, e.g. {@code resolve("examples/intralogistics")}. */
    public static Path resolve(String relative) {
        return path().resolve(relative);
    }

    /** The same as a File, for the tests written against java.io. */
    public static File file(String relative) {
        return resolve(relative).toFile();
    }

    private static Path find() {
        return find(System.getProperty("miron.root"), Path.of("").toAbsolutePath().normalize());
    }

    /** The root given the property (or null) and the folder to start walking up from. */
    static Path find(String property, Path start) {
        if (property != null) {
            Path given = Path.of(property).toAbsolutePath().normalize();
            if (!Files.isRegularFile(given.resolve("settings.gradle"))) {
                throw new IllegalStateException("miron.root=" + property + " is not the repository root (no settings.gradle there)");
            }
            return given;
        }
        for (Path dir = start; dir != null; dir = dir.getParent()) {
            if (Files.isRegularFile(dir.resolve("settings.gradle"))) {
                return dir;
            }
        }
        throw new IllegalStateException("no repository root: the system property miron.root is not set and no folder"
                + " from " + start + " upwards holds settings.gradle");
    }
}
