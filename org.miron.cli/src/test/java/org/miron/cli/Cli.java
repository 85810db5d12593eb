package org.miron.cli;

import java.io.PrintWriter;
import java.io.StringWriter;
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

    static int exit(String... args) {
        return new Cli().run(args);
    }
}
