package org.miron.ide.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.FileChangeType;
import org.eclipse.lsp4j.FileEvent;
import org.junit.Rule;
import org.junit.Test;
import org.miron.generator.standalone.ModelLoader;

/** The server's diagnostics are `miron check`'s, and follow the files on disk. */
public class DiagnosticsLspTest {
    @Rule
    public final ExampleSession session = new ExampleSession("intralogistics");

    @Test
    public void sameMessagesPositionsAndCodesAsMironCheck() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        Path bt = session.workspace.resolve("intralogistics.bt");
        Files.writeString(miron, Files.readString(miron).replace("roqme.safety++", "roqme.safty++")
                .replace("implies task = task::dock", "implies task = task::dok"));
        Files.writeString(bt, Files.readString(bt).replace("<SubTreePlus ID=\"PickDeliverCharge\"",
                "<SubTreePlus ID=\"PickDeliverChrge\"").replace("<Action ID=\"objectdrop\" obj_index=\"-1\"/>",
                "<RetryUntilSuccesful num_attempts=\"2\"><Action ID=\"objectdrop\" obj_index=\"-1\"/></RetryUntilSuccesful>"));

        ModelLoader check = new ModelLoader();
        check.load(miron.toFile());
        List<org.miron.generator.standalone.Diagnostic> expected = check.validateAll();
        assertFalse(expected.isEmpty());

        for (Path file : List.of(miron, bt)) {
            String uri = session.client.open(file);
            Set<String> fromCheck = expected.stream()
                    .filter(d -> Path.of(d.file()).toAbsolutePath().normalize().equals(file.toAbsolutePath().normalize()))
                    .map(d -> d.line() + ":" + d.column() + " " + d.severity() + " [" + d.code() + "] " + d.message())
                    .collect(Collectors.toCollection(TreeSet::new));
            List<Diagnostic> published = session.client.awaitDiagnostics(uri, ds -> ds.size() >= fromCheck.size());
            Set<String> fromServer = published.stream()
                    .filter(d -> d.getSeverity() == DiagnosticSeverity.Error || d.getSeverity() == DiagnosticSeverity.Warning)
                    .map(d -> (d.getRange().getStart().getLine() + 1) + ":" + (d.getRange().getStart().getCharacter() + 1)
                            + " " + (d.getSeverity() == DiagnosticSeverity.Error ? "error" : "warning") + " ["
                            + d.getCode().getLeft() + "] " + LspClient.message(d).replaceAll("\\s*\\R\\s*", " "))
                    .collect(Collectors.toCollection(TreeSet::new));
            assertFalse(file.toString(), fromCheck.isEmpty());
            assertEquals(file.toString(), fromCheck, fromServer);
        }
    }

    @Test
    public void anImportedFileDeletedAndCreatedOnDisk() throws Exception {
        Path roqme = session.workspace.resolve("intralogistics.roqme");
        Path moved = session.workspace.resolve("elsewhere.txt");
        String mironUri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
        Files.move(roqme, moved);
        session.client.server().getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(
                List.of(new FileEvent(LspClient.uri(roqme), FileChangeType.Deleted))));
        session.client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);

        Files.move(moved, roqme);
        session.client.server().getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(
                List.of(new FileEvent(LspClient.uri(roqme), FileChangeType.Created))));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
    }

    @Test
    public void theHospitalExampleHasNoErrorsEither() throws Exception {
        Path hospital = Workspaces.copyOfExample("hospital-delivery");
        try (LspClient other = new LspClient()) {
            other.initialize(hospital);
            for (String file : List.of("hospital.miron", "hospital.roqme", "hospital.bt")) {
                String uri = other.open(hospital.resolve(file));
                other.awaitDiagnostics(uri, d -> true);
                assertFalse(file + ": " + other.published(uri), IntralogisticsLspTest.hasErrors(other.published(uri)));
            }
        } finally {
            Workspaces.delete(hospital);
        }
    }

    @Test
    public void aFileChangedOnDiskRevalidatesItsImporters() throws Exception {
        Path roqme = session.workspace.resolve("intralogistics.roqme");
        String mironUri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));

        // The .roqme is not open: only the file on disk and the watcher's event tell the server.
        String original = Files.readString(roqme);
        Files.writeString(roqme, original.replace("property safety ", "property safetyX "));
        session.client.server().getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(
                List.of(new FileEvent(LspClient.uri(roqme), FileChangeType.Changed))));
        List<Diagnostic> broken = session.client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);
        assertTrue(broken.toString(), broken.stream().anyMatch(d -> LspClient.message(d).contains("safety")));

        Files.writeString(roqme, original);
        session.client.server().getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(
                List.of(new FileEvent(LspClient.uri(roqme), FileChangeType.Changed))));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
    }
}
