package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.InitializeResult;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** The language server as an editor starts it: a child process speaking LSP on stdio. */
public class ProcessLspTest {

    /** The command line of the server process; `miron lsp` runs the same entry point. */
    static List<String> serverCommand() {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> command = new ArrayList<>(List.of(java, "-Xss4m", "-cp",
                System.getProperty("miron.lsp.classpath", System.getProperty("java.class.path"))));
        command.add(MironLanguageServer.class.getName());
        return command;
    }

    @Test
    public void answersOverStdioAndExitsCleanly() throws Exception {
        Path workspace = Examples.copy("intralogistics");
        Process process = new ProcessBuilder(serverCommand())
                .redirectError(ProcessBuilder.Redirect.appendTo(new File(workspace.toFile(), "server.log"))).start();
        try {
            LspClient client = new LspClient(process.getInputStream(), process.getOutputStream());
            InitializeResult result = client.initialize(workspace);
            assertTrue(result.getCapabilities().getCompletionProvider().getTriggerCharacters().containsAll(List.of(".", ":", "<")));
            assertTrue(result.getCapabilities().getExecuteCommandProvider().getCommands().contains("miron.generate"));
            assertTrue(result.getCapabilities().getExecuteCommandProvider().getCommands().contains("miron.convert"));
            String uri = client.open(workspace.resolve("intralogistics.miron"));
            client.awaitDiagnostics(uri, d -> !IntralogisticsLspTest.hasErrors(d));
            client.close(); // shutdown, exit, end of input: as an editor ends the session
            assertTrue("the server did not exit", process.waitFor(60, TimeUnit.SECONDS));
            assertEquals(0, process.exitValue());
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
    }
}
