package org.miron.gradle;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Enumeration;
import java.util.Properties;
import java.util.TreeSet;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

/**
 * The Gradle that TestKit runs the user projects with: the one running this build
 * (`gradle.gradleHomeDir`, the `miron.gradle.home` property). Debian's package keeps the libraries
 * Gradle needs (slf4j, Guava, ...) in /usr/share/java, named in each Gradle jar's
 * `*-classpath.properties`, while TestKit's tooling API loads Gradle from the installation's lib/
 * folder only: for such an installation this builds one of links, lib/ holding both. An upstream
 * distribution, which has them all in lib/, is used as it is.
 */
final class TestKitGradle {
    private static final Path SYSTEM_JARS = Path.of("/usr/share/java");

    private TestKitGradle() {
    }

    static synchronized File installation() {
        Path home = Path.of(System.getProperty("miron.gradle.home"));
        try {
            TreeSet<String> external = externalJars(home);
            if (external.isEmpty()) {
                return home.toFile();
            }
            Path linked = Path.of(System.getProperty("miron.testkit.dir"), "gradle-" + home.getFileName());
            if (!Files.isDirectory(linked)) {
                Path staging = Files.createTempDirectory(linked.getParent() == null ? Path.of(".") : createParent(linked), "gradle");
                link(home, staging);
                for (String jar : external) {
                    Files.createSymbolicLink(staging.resolve("lib").resolve(jar), SYSTEM_JARS.resolve(jar));
                }
                Files.move(staging, linked);
            }
            return linked.toFile();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Path createParent(Path path) throws IOException {
        return Files.createDirectories(path.getParent());
    }

    /** The installation's tree (bin, lib, lib/plugins, init.d) as links to its files. */
    private static void link(Path home, Path target) throws IOException {
        try (Stream<Path> paths = Files.walk(home)) {
            for (Path p : (Iterable<Path>) paths::iterator) {
                Path copy = target.resolve(home.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(copy);
                } else {
                    Files.createSymbolicLink(copy, p);
                }
            }
        }
    }

    /** The libraries Gradle's jars name that are not in lib/ but in /usr/share/java. */
    private static TreeSet<String> externalJars(Path home) throws IOException {
        TreeSet<String> names = new TreeSet<>();
        try (Stream<Path> jars = Files.walk(home.resolve("lib"))) {
            for (Path jar : (Iterable<Path>) jars.filter(p -> p.toString().endsWith(".jar"))::iterator) {
                names.addAll(runtimeOf(jar.toFile()));
            }
        }
        names.removeIf(name -> Files.exists(home.resolve("lib").resolve(name)) || !Files.exists(SYSTEM_JARS.resolve(name)));
        return names;
    }

    private static TreeSet<String> runtimeOf(File jar) throws IOException {
        TreeSet<String> names = new TreeSet<>();
        try (ZipFile zip = new ZipFile(jar)) {
            for (Enumeration<? extends ZipEntry> e = zip.entries(); e.hasMoreElements();) {
                ZipEntry entry = e.nextElement();
                if (entry.getName().endsWith("-classpath.properties") && !entry.getName().contains("/")) {
                    Properties properties = new Properties();
                    try (InputStream in = zip.getInputStream(entry)) {
                        properties.load(in);
                    }
                    for (String name : properties.getProperty("runtime", "").split(",")) {
                        if (!name.isBlank()) {
                            names.add(name.trim());
                        }
                    }
                }
            }
        }
        return names;
    }
}
