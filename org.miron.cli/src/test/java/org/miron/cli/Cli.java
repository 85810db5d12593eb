package org.miron.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import picocli.CommandLine;
import org.miron.testkit.RepositoryRoot;

/** Runs the `miron` command line in-process and keeps what it printed. */
final class Cli {
    static final Path ROOT = RepositoryRoot.path();

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

    /** Writes a file (and the folders above it) below dir, for a command to read. */
    static Path write(Path dir, String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        return file;
    }

    static int exit(String... args) {
        return new Cli().run(args);
    }
}
