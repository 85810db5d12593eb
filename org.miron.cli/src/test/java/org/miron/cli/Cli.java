package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;


import picocli.CommandLine;

/** Runs the `miron` command line in-process and keeps what it printed. */
final class Cli {
    static final Path ROOT = Path.of(System.getProperty("miron.root", "..")).toAbsolutePath().normalize();

    final StringWriter out = new StringWriter();
    final StringWriter err = new StringWriter();

    int run(String... args) {
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        return cli.execute(args);
    }

    String out() {
        return out.toString().replace(System.lineSeparator(), "\n");
    }

    static int exit(String... args) {
        return new Cli().run(args);
    }

    /** Copies a folder of test resources (src/test/resources/NAME) to dir. */
    static Path copyResources(String name, Path dir) {
        Path from = ROOT.resolve("org.miron.generator/src/test/resources").resolve(name);
        try (Stream<Path> files = Files.walk(from)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                Path to = dir.resolve(from.relativize(file).toString());
                if (Files.isDirectory(file)) {
                    Files.createDirectories(to);
                } else {
                    Files.copy(file, to);
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return dir;
    }
}
