package org.miron.lsp.server;

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
import org.miron.generator.standalone.Diagnostic.Severity;
import org.miron.generator.standalone.ModelLoader;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

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

        assertSameAsMironCheck(miron, List.of(miron, bt));
    }

    /** Timers, schedules and their warnings: the server underlines the very cron field `miron check` names. */
    @Test
    public void timerAndScheduleDiagnosticsAreMironChecks() throws Exception {
        Path roqme = session.workspace.resolve("intralogistics.roqme");
        String text = Files.readString(roqme) + """

                /** Rounds at 8 on weekdays. */
                timer rounds := schedule("0 8 * * MON-FRY")
                timer forgotten paused := 5 minutes
                timer zero := 0 seconds
                var wrong : number := sinceLastDelivery + 1
                observation onRounds : rounds /**/ reinforces safety
                """;
        Files.writeString(roqme, text);
        List<org.miron.generator.standalone.Diagnostic> expected = assertSameAsMironCheck(roqme, List.of(roqme));
        assertEquals(expected.toString(), 3, expected.stream().filter(d -> d.severity() == Severity.ERROR).count());
        assertEquals(expected.toString(), 1, expected.stream().filter(d -> d.severity() == Severity.WARNING).count());
        // MON-FRY: the error starts at FRY
        String rounds = "timer rounds := schedule(\"0 8 * * MON-";
        assertTrue(expected.toString(), expected.stream().anyMatch(d -> d.code().equals("roqme.invalid-schedule")
                && d.column() == rounds.length() + 1));

        String uri = LspClient.uri(roqme);
        org.eclipse.lsp4j.Hover hover = session.client.server().getTextDocumentService()
                .hover(new org.eclipse.lsp4j.HoverParams(new org.eclipse.lsp4j.TextDocumentIdentifier(uri),
                        IntralogisticsLspTest.positionAfter(text, "observation onRounds : roun")))
                .get(60, java.util.concurrent.TimeUnit.SECONDS);
        String shown = hover.getContents().getRight().getValue();
        assertTrue(shown, shown.contains("Rounds at 8 on weekdays."));
    }

    /** The rule check (miron.rule-conflict and its witness) reaches the editor as `miron check` prints it. */
    @Test
    public void ruleConflictsAreWarnedAsByMironCheck() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        Files.writeString(miron, Files.readString(miron) + "\nrule rush : roqme.safety > 0.8 implies task = task::pick\n");
        List<org.miron.generator.standalone.Diagnostic> expected = assertSameAsMironCheck(miron, List.of(miron));
        assertTrue(expected.toString(), expected.stream().anyMatch(d -> d.code().equals("miron.rule-conflict")
                && d.message().equals("rules noBattery and rush conflict when power_autonomy < 0.3 and safety > 0.8; noBattery wins")));
    }

    /**
     * Opens the files and checks that the server publishes for each exactly what `miron check`
     * reports for it (message, position, severity and code) when loading the first; returns those.
     */
    private List<org.miron.generator.standalone.Diagnostic> assertSameAsMironCheck(Path loaded, List<Path> files)
            throws Exception {
        ModelLoader check = new ModelLoader();
        check.load(loaded.toFile());
        List<org.miron.generator.standalone.Diagnostic> expected = check.validateAll();
        assertFalse(expected.isEmpty());

        for (Path file : files) {
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
        return expected;
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
        Path hospital = Examples.copy("hospital-delivery");
        try (LspClient other = new LspClient()) {
            other.initialize(hospital);
            for (String file : List.of("hospital.miron", "hospital.roqme", "hospital.bt")) {
                String uri = other.open(hospital.resolve(file));
                other.awaitDiagnostics(uri, d -> true);
                assertFalse(file + ": " + other.published(uri), IntralogisticsLspTest.hasErrors(other.published(uri)));
            }
        } finally {
            Folders.delete(hospital);
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
