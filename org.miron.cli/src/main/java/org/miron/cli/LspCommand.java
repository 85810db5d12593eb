package org.miron.cli;

import java.io.IOException;
import java.util.concurrent.Callable;

import org.miron.lsp.server.MironLanguageServer;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** `miron lsp [--socket PORT]`: the language server for .bt/.xml, .roqme and .miron files. */
@Command(name = "lsp", mixinStandardHelpOptions = true,
        description = { "Runs the MIRoN language server (Language Server Protocol) for behaviour trees (.bt, woven .xml), "
                + "RoQME (.roqme) and MIRoN (.miron) files: diagnostics as `miron check`, completion, hover, go to "
                + "definition, references, outline, formatting, folding, quick fixes and the commands miron.generate "
                + "and miron.convert.",
                "By default it speaks LSP on standard input and output, as editors start it; with --socket it "
                        + "listens on 127.0.0.1 only and serves each client that connects." },
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:the client asked the server to exit after shutdown", "1:the client exited without shutdown, "
                + "or the socket could not be opened", "2:usage error" })
public class LspCommand implements Callable<Integer> {

    @Option(names = "--socket", paramLabel = "PORT",
            description = "Listen on 127.0.0.1:PORT instead of using standard input and output.")
    Integer port;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        if (port == null) {
            MironLanguageServer.serveStdio();
            return 0;
        }
        if (port < 0 || port > 65535) {
            spec.commandLine().getErr().println("miron lsp: --socket needs a port from 0 to 65535, not " + port);
            return 2;
        }
        try {
            MironLanguageServer.serveSocket(port);
            return 0;
        } catch (IOException e) {
            spec.commandLine().getErr().println("miron lsp: cannot listen on 127.0.0.1:" + port + ": " + e.getMessage());
            return 1;
        }
    }
}
