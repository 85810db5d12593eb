package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.DiagnosticSeverity;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

import picocli.CommandLine;

/** `miron lsp`: started as editors start it, a child process speaking LSP on stdio. */
public class LspCommandTest {

    @Test
    public void helpDescribesStdioAndSocket() {
        StringWriter out = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out));
        assertEquals(0, cli.execute("lsp", "--help"));
        assertTrue(out.toString(), out.toString().contains("--socket=PORT"));
        assertTrue(out.toString(), out.toString().contains("standard input and output"));
    }

    @Test
    public void answersAnEditorOverStdio() throws Exception {
        Path workspace = Examples.copy("intralogistics");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // With Guice's reflection instead of its generated classes, as ./miron lsp runs the server.
        Process process = new ProcessBuilder(java, "-Xss4m", "-Dguice_bytecode_gen_option=DISABLED", "-cp",
                System.getProperty("miron.cli.classpath", System.getProperty("java.class.path")),
                MironCli.class.getName(), "lsp")
                .redirectError(ProcessBuilder.Redirect.appendTo(new File(workspace.toFile(), "server.log"))).start();
        try {
            LspClient client = new LspClient(process.getInputStream(), process.getOutputStream());
            client.initialize(workspace);
            String uri = client.open(workspace.resolve("intralogistics.miron"));
            client.awaitDiagnostics(uri, d -> d.stream().noneMatch(x -> x.getSeverity() == DiagnosticSeverity.Error));
            client.close(); // shutdown, exit, end of input: as an editor ends the session
            assertTrue("miron lsp did not exit", process.waitFor(60, TimeUnit.SECONDS));
            assertEquals(0, process.exitValue());
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
    }

    @Test
    public void aBadPortIsAUsageError() {
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setErr(new PrintWriter(err));
        assertEquals(2, cli.execute("lsp", "--socket", "70000"));
        assertTrue(err.toString(), err.toString().contains("0 to 65535"));
    }
}
