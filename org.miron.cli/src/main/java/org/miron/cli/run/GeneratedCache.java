package org.miron.cli.run;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * What {@code miron run} generated before, kept between runs: a robot restarts with the same
 * model far more often than the model changes, and generating means loading Xtext, seconds of
 * start-up. An entry holds a generation and its manifest: the toolchain's fingerprint and the
 * SHA-256 of every file the generation read (the model and all it imports). It is used only while
 * all of them are unchanged. Entries are never rewritten (a running robot may be reading one): a
 * new generation is a new folder, and {@code KEY.last} names a model's latest.
 */
final class GeneratedCache {
    static final String MANIFEST = "manifest.txt";
    private static final int KEEP = 32; // entries beyond the most recent are deleted
    private final Path root;

    GeneratedCache(Path root) {
        this.root = root;
    }

    /** {@code $XDG_CACHE_HOME/miron/run}, or {@code ~/.cache/miron/run}. */
    static Path defaultRoot() {
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("miron").resolve("run");
    }

    Path root() {
        return root;
    }

    /** The model's last generation, if the toolchain and every file it read are as they were. */
    Optional<Path> lookup(Path model) {
        try {
            Path last = root.resolve(key(model) + ".last");
            if (!Files.isRegularFile(last)) {
                return Optional.empty();
            }
            Path entry = root.resolve(Files.readString(last, StandardCharsets.UTF_8).trim());
            Path manifest = entry.resolve(MANIFEST);
            if (!Files.isRegularFile(manifest) || !Files.readString(manifest, StandardCharsets.UTF_8).equals(manifest(inputs(manifest)))) {
                return Optional.empty();
            }
            return Optional.of(entry);
        } catch (IOException | UncheckedIOException | IllegalArgumentException e) {
            return Optional.empty(); // unreadable or half written: generate again
        }
    }

    /** A fresh folder in the cache to generate into. */
    Path staging() throws IOException {
        Files.createDirectories(root);
        return Files.createTempDirectory(root, "staging-");
    }

    /**
     * Makes a finished generation in {@code staged} the model's entry, with the manifest of the
     * files it read; returns the entry (an identical one made meanwhile by another run is reused).
     */
    Path store(Path model, Path staged, List<Path> read) throws IOException {
        String manifest = manifest(read);
        String name = key(model) + "-" + sha256(manifest.getBytes(StandardCharsets.UTF_8)).substring(0, 16);
        Path entry = root.resolve(name);
        Files.writeString(staged.resolve(MANIFEST), manifest, StandardCharsets.UTF_8);
        if (Files.isDirectory(entry)) {
            delete(staged);
        } else {
            try {
                Files.move(staged, entry, StandardCopyOption.ATOMIC_MOVE);
            } catch (java.nio.file.FileSystemException e) {
                if (!Files.isDirectory(entry)) {
                    throw e;
                }
                delete(staged); // the same generation, stored by a run at the same time
            }
        }
        Path last = Files.createTempFile(root, "last-", ".tmp");
        Files.writeString(last, name, StandardCharsets.UTF_8);
        Files.move(last, root.resolve(key(model) + ".last"), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        evict();
        return entry;
    }

    /** The toolchain's fingerprint, then "sha256 path" per file read. */
    private static String manifest(List<Path> read) throws IOException {
        StringBuilder b = new StringBuilder("toolchain ").append(toolchain()).append('\n');
        for (Path p : read) {
            b.append(sha256(Files.readAllBytes(p))).append(' ').append(p).append('\n');
        }
        return b.toString();
    }

    private static List<Path> inputs(Path manifest) throws IOException {
        List<Path> read = new ArrayList<>();
        for (String line : Files.readAllLines(manifest, StandardCharsets.UTF_8)) {
            if (!line.startsWith("toolchain ") && line.length() > 65) {
                read.add(Path.of(line.substring(65)));
            }
        }
        return read;
    }

    /** The class path's entries with their sizes and times: a rebuilt or updated toolchain generates again. */
    private static String toolchain() throws IOException {
        StringBuilder b = new StringBuilder();
        for (String entry : System.getProperty("java.class.path").split(java.io.File.pathSeparator)) {
            Path p = Path.of(entry);
            b.append(entry);
            if (Files.isRegularFile(p)) {
                b.append('|').append(Files.size(p)).append('|').append(Files.getLastModifiedTime(p).toMillis());
            }
            b.append('\n');
        }
        return sha256(b.toString().getBytes(StandardCharsets.UTF_8)).substring(0, 32);
    }

    private static String key(Path model) {
        return sha256(model.toAbsolutePath().normalize().toString().getBytes(StandardCharsets.UTF_8)).substring(0, 20);
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e); // every JDK has SHA-256
        }
    }

    /** Keeps the most recent entries; a staging folder left by a killed run goes after a day. */
    private void evict() {
        try (Stream<Path> all = Files.list(root)) {
            List<Path> entries = new ArrayList<>();
            long dayAgo = System.currentTimeMillis() - 86_400_000L;
            for (Path p : all.toList()) {
                if (!Files.isDirectory(p)) {
                    continue;
                }
                if (p.getFileName().toString().startsWith("staging-")) {
                    if (Files.getLastModifiedTime(p).toMillis() < dayAgo) {
                        delete(p);
                    }
                } else {
                    entries.add(p);
                }
            }
            entries.sort(Comparator.comparingLong((Path p) -> p.toFile().lastModified()).reversed());
            for (Path old : entries.subList(Math.min(KEEP, entries.size()), entries.size())) {
                delete(old);
            }
        } catch (IOException e) {
            // a cache that cannot be tidied still works
        }
    }

    static void delete(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // left behind: evicted later
        }
    }
}
