package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** The intralogistics example through a real LSP client: the scenarios of the language-server issue. */
public class IntralogisticsLspTest {
    private Path workspace;
    private LspClient client;
    private Path miron;
    private Path roqme;
    private Path bt;

    @Before
    public void setUp() throws Exception {
        workspace = Examples.copy("intralogistics");
        miron = workspace.resolve("intralogistics.miron");
        roqme = workspace.resolve("intralogistics.roqme");
        bt = workspace.resolve("intralogistics.bt");
        client = new LspClient();
        client.initialize(workspace);
    }

    @After
    public void tearDown() throws Exception {
        client.close();
        Folders.delete(workspace);
    }

    static boolean hasErrors(List<Diagnostic> diagnostics) {
        return diagnostics.stream().anyMatch(d -> d.getSeverity() == DiagnosticSeverity.Error);
    }

    @Test
    public void theExampleHasNoErrors() throws Exception {
        String uri = client.open(miron);
        assertEquals(List.of(), client.awaitDiagnostics(uri, d -> true).stream()
                .filter(d -> d.getSeverity() == DiagnosticSeverity.Error).collect(Collectors.toList()));
    }

    @Test
    public void editingTheImportedRoqmeBufferRevalidatesTheMiron() throws Exception {
        String mironUri = client.open(miron);
        client.awaitDiagnostics(mironUri, d -> !hasErrors(d));
        String roqmeText = Files.readString(roqme);
        String roqmeUri = client.open(roqme, roqmeText);

        // Unsaved: the file on disk still declares `safety`.
        client.change(roqmeUri, roqmeText.replace("property safety ", "property safetyX "));
        List<Diagnostic> broken = client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);
        assertTrue(broken.toString(), broken.stream().anyMatch(d -> LspClient.message(d).contains("safety")));

        client.change(roqmeUri, roqmeText);
        client.awaitDiagnostics(mironUri, d -> !hasErrors(d));
    }

    /**
     * Issue 23, item 9: a renamed tree whose old name is still a node's name (the example's
     * `<Sequence name="Charge">`): the message says no tree has the ID and names the trees.
     */
    @Test
    public void aTreeRenamedAwayIsReportedAsNoSuchTree() throws Exception {
        String mironUri = client.open(miron);
        client.awaitDiagnostics(mironUri, d -> !hasErrors(d));
        String btText = Files.readString(bt);
        String btUri = client.open(bt, btText);
        client.change(btUri, btText.replace("<BehaviorTree ID=\"Charge\">", "<BehaviorTree ID=\"Dock\">"));
        List<Diagnostic> broken = client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);
        String messages = broken.stream().map(LspClient::message).collect(java.util.stream.Collectors.joining("\n"));
        assertTrue(messages, messages.contains("unknown behavior tree 'main.Charge': no BehaviorTree has this ID"));
        assertTrue(messages, messages.contains("main.Dock"));
        assertFalse(messages, messages.contains("not a behavior tree"));
    }

    @Test
    public void editingTheImportedTreeBufferRevalidatesTheMiron() throws Exception {
        String mironUri = client.open(miron);
        client.awaitDiagnostics(mironUri, d -> !hasErrors(d));
        String btText = Files.readString(bt);
        String btUri = client.open(bt, btText);
        client.change(btUri, btText.replace("<BehaviorTree ID=\"DeliverCharge\">", "<BehaviorTree ID=\"DeliverAndCharge\">"));
        List<Diagnostic> broken = client.awaitDiagnostics(mironUri, IntralogisticsLspTest::hasErrors);
        assertTrue(broken.toString(), broken.stream().anyMatch(d -> LspClient.message(d).contains("DeliverCharge")));
        client.change(btUri, btText);
        client.awaitDiagnostics(mironUri, d -> !hasErrors(d));
    }

    @Test
    public void hoverOnAnImportedTreeShowsItsXmlComment() throws Exception {
        String btText = Files.readString(bt).replace("<BehaviorTree ID=\"Charge\">",
                "<!-- Drives to the dock and charges. -->\n  <BehaviorTree ID=\"Charge\">");
        client.awaitDiagnostics(client.open(bt, btText), d -> true);
        String text = Files.readString(miron);
        String uri = client.open(miron, text);
        client.awaitDiagnostics(uri, d -> !hasErrors(d));
        org.eclipse.lsp4j.Hover hover = client.server().getTextDocumentService()
                .hover(new org.eclipse.lsp4j.HoverParams(new TextDocumentIdentifier(uri), positionAfter(text, "dock : main.Cha")))
                .get(60, TimeUnit.SECONDS);
        assertTrue(String.valueOf(hover), hover.getContents().getRight().getValue().contains("Drives to the dock and charges."));
    }

    @Test
    public void completionAfterTheAliasOffersTheImportedTrees() throws Exception {
        String uri = client.open(miron);
        client.awaitDiagnostics(uri, d -> true);
        Position afterMainDot = positionAfter(Files.readString(miron), "pick : main.");
        List<String> labels = labels(client.server().getTextDocumentService()
                .completion(new CompletionParams(new TextDocumentIdentifier(uri), afterMainDot))
                .get(60, TimeUnit.SECONDS));
        assertTrue(labels.toString(), labels.stream().anyMatch(l -> l.endsWith("PickDeliverCharge")));
        assertTrue(labels.toString(), labels.stream().anyMatch(l -> l.endsWith("Charge")));
    }

    @Test
    public void definitionGoesFromTheMironIntoTheBehaviourTree() throws Exception {
        String uri = client.open(miron);
        client.awaitDiagnostics(uri, d -> true);
        Position onTree = positionAfter(Files.readString(miron), "deliver : main.Deliv");
        List<? extends Location> locations = client.server().getTextDocumentService()
                .definition(new DefinitionParams(new TextDocumentIdentifier(uri), onTree)).get(60, TimeUnit.SECONDS)
                .getLeft();
        assertEquals(1, locations.size());
        Location target = locations.get(0);
        assertEquals(LspClient.uri(bt), target.getUri());
        String line = Files.readAllLines(bt).get(target.getRange().getStart().getLine());
        assertTrue(line, line.contains("<BehaviorTree ID=\"DeliverCharge\""));
    }

    @Test
    public void definitionGoesToTheBtNodeAndTheRoqmeProperty() throws Exception {
        String uri = client.open(miron);
        client.awaitDiagnostics(uri, d -> true);
        String text = Files.readString(miron);
        assertTrue(definitionLine(uri, text, "} in main.PickDeliverChargeSub", bt)
                .contains("name=\"PickDeliverChargeSubtree\""));
        assertTrue(definitionLine(uri, text, "10 affects roqme.saf", roqme).contains("property safety"));
        assertTrue(definitionLine(uri, text, "rule noBattery : roqme.power_auto", roqme).contains("property power_autonomy"));
    }

    /** The line of the definition of what is just before the end of `after`, in the expected file. */
    private String definitionLine(String uri, String text, String after, Path expectedFile) throws Exception {
        List<? extends Location> locations = client.server().getTextDocumentService()
                .definition(new DefinitionParams(new TextDocumentIdentifier(uri), positionAfter(text, after)))
                .get(60, TimeUnit.SECONDS).getLeft();
        assertEquals(after, 1, locations.size());
        assertEquals(LspClient.uri(expectedFile), locations.get(0).getUri());
        return Files.readAllLines(expectedFile).get(locations.get(0).getRange().getStart().getLine());
    }

    @Test
    public void formattingIndentsABehaviourTree() throws Exception {
        String text = Files.readString(bt).replace("\n      <Action ID=\"objectdrop\"", "\n<Action ID=\"objectdrop\"");
        String uri = client.open(bt, text);
        client.awaitDiagnostics(uri, d -> true);
        List<? extends TextEdit> edits = client.server().getTextDocumentService()
                .formatting(new DocumentFormattingParams(new TextDocumentIdentifier(uri), new FormattingOptions(2, true)))
                .get(60, TimeUnit.SECONDS);
        assertTrue(TextEdits.apply(text, edits).contains("\n      <Action ID=\"objectdrop\""));
    }

    @Test
    public void formattingFixesTheLayout() throws Exception {
        String text = Files.readString(miron).replace("rule noBattery : roqme.power_autonomy < 0.3",
                "rule   noBattery :   roqme.power_autonomy<0.3");
        String uri = client.open(miron, text);
        client.awaitDiagnostics(uri, d -> true);
        List<? extends TextEdit> edits = client.server().getTextDocumentService()
                .formatting(new DocumentFormattingParams(new TextDocumentIdentifier(uri), new FormattingOptions(2, true)))
                .get(60, TimeUnit.SECONDS);
        assertFalse(edits.isEmpty());
        assertTrue(edits.toString(), TextEdits.apply(text, edits).contains("rule noBattery : roqme.power_autonomy < 0.3"));
    }

    private String formatted(Path file, FormattingOptions options) throws Exception {
        String text = Files.readString(file);
        String uri = client.open(file, text);
        client.awaitDiagnostics(uri, d -> true);
        return TextEdits.apply(text, client.server().getTextDocumentService()
                .formatting(new DocumentFormattingParams(new TextDocumentIdentifier(uri), options)).get(60, TimeUnit.SECONDS));
    }

    /**
     * Issue 23, item 10: the examples are formatter-clean through the server too, and the client's
     * indentation (tabSize, insertSpaces) is the one used.
     */
    @Test
    public void formattingKeepsTheExamplesAndUsesTheClientsIndentation() throws Exception {
        for (Path file : List.of(miron, roqme, bt)) {
            assertEquals(file.toString(), Files.readString(file), formatted(file, new FormattingOptions(2, true)));
        }
        assertTrue(formatted(miron, new FormattingOptions(4, true)).contains("\n    10 affects roqme.safety++,\n"));
        assertTrue(formatted(miron, new FormattingOptions(4, false)).contains("\n\t10 affects roqme.safety++,\n"));
        assertTrue(formatted(bt, new FormattingOptions(4, true)).contains("\n    <BehaviorTree ID=\"Main\">\n"));
        assertTrue(formatted(bt, new FormattingOptions(3, false)).contains("\n\t<BehaviorTree ID=\"Main\">\n"));
    }

    static List<String> labels(Either<List<CompletionItem>, CompletionList> result) {
        List<CompletionItem> items = result.isLeft() ? result.getLeft() : result.getRight().getItems();
        return items.stream().map(CompletionItem::getLabel).collect(Collectors.toList());
    }

    /** The position just after the first occurrence of a text. */
    static Position positionAfter(String document, String text) {
        int offset = document.indexOf(text);
        if (offset < 0) {
            throw new AssertionError("not in the document: " + text);
        }
        return TextEdits.position(document, offset + text.length());
    }
}
