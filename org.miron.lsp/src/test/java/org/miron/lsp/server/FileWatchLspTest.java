package org.miron.lsp.server;

import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.lsp4j.DidChangeWatchedFilesCapabilities;
import org.eclipse.lsp4j.Registration;
import org.junit.Rule;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * Issue 23, item 2: changes on disk reach the server whatever the client. This client sends no
 * workspace/didChangeWatchedFiles (as Neovim on Linux): the server watches the folder itself.
 */
public class FileWatchLspTest {
    @Rule
    public final ExampleSession session = new ExampleSession("intralogistics");

    @Test
    public void aRoqmeRenamedOnDiskIsSeenWithoutTheClientsEvents() throws Exception {
        Path roqme = session.workspace.resolve("intralogistics.roqme");
        Path moved = session.workspace.resolve("renamed.roqme");
        String mironUri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));

        // Twice: the watch goes on after the first round trip.
        for (int round = 0; round < 2; round++) {
            Files.move(roqme, moved);
            session.client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);
            Files.move(moved, roqme);
            session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
        }
    }

    @Test
    public void aFileEditedOnDiskInANewSubfolderIsSeen() throws Exception {
        String mironUri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
        Path sub = session.workspace.resolve("more");
        Files.createDirectories(sub);
        Path extra = sub.resolve("extra.roqme");
        Files.writeString(extra, "roqme Extra\ncontext C : nosuchtype\n");
        session.client.awaitDiagnostics(LspClient.uri(extra), IntralogisticsLspTest::hasErrors);
        Files.writeString(extra, "roqme Extra\ncontext C : boolean\n");
        session.client.awaitDiagnostics(LspClient.uri(extra), d -> !IntralogisticsLspTest.hasErrors(d));
    }

    /** A client that can watch files is asked to, for the model files. */
    @Test
    public void aClientThatCanWatchIsAskedTo() throws Exception {
        Path other = Examples.copy("intralogistics");
        try (LspClient watching = new LspClient()) {
            watching.initialize(other, capabilities -> capabilities.getWorkspace()
                    .setDidChangeWatchedFiles(new DidChangeWatchedFilesCapabilities(true)));
            Registration registration = watching.awaitRegistration("workspace/didChangeWatchedFiles");
            // The options arrive as JSON: the client reads them as it likes.
            String options = String.valueOf(registration.getRegisterOptions());
            assertTrue(options, options.contains(FileChangeSource.GLOB));
        } finally {
            Folders.delete(other);
        }
    }
}
