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

    /**
     * Issue 23, item 12: the server warms rename up in the background after start-up (RenameWarmUp);
     * it ends, changes no file and sends no edit, and renames answer as before.
     */
    @Test
    public void theRenameWarmUpChangesNothing() throws Exception {
        Path workspace = Examples.copy("intralogistics");
        List<String> command = serverCommand();
        command.add(command.size() - 1, "-Dmiron.lsp.timing=true"); // its milestones on standard error
        File log = new File(workspace.toFile(), "server.log");
        Process process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.appendTo(log)).start();
        try {
            String bt = java.nio.file.Files.readString(workspace.resolve("intralogistics.bt"));
            String miron = java.nio.file.Files.readString(workspace.resolve("intralogistics.miron"));
            LspClient client = new LspClient(process.getInputStream(), process.getOutputStream());
            client.initialize(workspace);
            String uri = client.open(workspace.resolve("intralogistics.miron"));
            client.awaitDiagnostics(uri, d -> !IntralogisticsLspTest.hasErrors(d));
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(180);
            while (!java.nio.file.Files.readString(log.toPath()).contains("rename warmed up in a .miron")) {
                assertTrue("no warm-up in the log:\n" + java.nio.file.Files.readString(log.toPath()),
                        System.nanoTime() < deadline && process.isAlive());
                Thread.sleep(50);
            }
            String logText = java.nio.file.Files.readString(log.toPath());
            assertTrue(logText, logText.contains("rename warmed up in a .bt") && logText.contains("rename warmed up in a .roqme"));
            org.eclipse.lsp4j.WorkspaceEdit edit = client.server().getTextDocumentService().rename(
                    new org.eclipse.lsp4j.RenameParams(new org.eclipse.lsp4j.TextDocumentIdentifier(uri),
                            IntralogisticsLspTest.positionAfter(miron, "dock : main.Cha"), "Dock"))
                    .get(60, TimeUnit.SECONDS);
            String renamed = TextEdits.apply(bt, edit.getChanges().get(LspClient.uri(workspace.resolve("intralogistics.bt"))));
            assertTrue(renamed, renamed.contains("<BehaviorTree ID=\"Dock\">"));
            assertEquals(bt, java.nio.file.Files.readString(workspace.resolve("intralogistics.bt")));
            assertEquals(miron, java.nio.file.Files.readString(workspace.resolve("intralogistics.miron")));
            assertTrue(client.appliedEdits.toString(), client.appliedEdits.isEmpty());
            assertTrue(client.published(uri).toString(), !IntralogisticsLspTest.hasErrors(client.published(uri)));
            client.close();
            assertTrue("the server did not exit", process.waitFor(60, TimeUnit.SECONDS));
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
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
