package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FoldingRange;
import org.eclipse.lsp4j.FoldingRangeRequestParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.SemanticTokensParams;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** Hover, references, rename, outline and folding across the intralogistics files. */
public class NavigationLspTest {
    private static Path workspace;
    private static LspClient client;
    private static String mironText;
    private static String mironUri;

    @BeforeClass
    public static void setUp() throws Exception {
        workspace = Examples.copy("intralogistics");
        client = new LspClient();
        client.initialize(workspace);
        mironText = Files.readString(workspace.resolve("intralogistics.miron")) + "\nrule r2 : roqme.safety < 0.3 implies task = task::dock\n";
        mironUri = client.open(workspace.resolve("intralogistics.miron"), mironText);
        client.awaitDiagnostics(mironUri, d -> true);
    }

    @AfterClass
    public static void tearDown() throws Exception {
        client.close();
        Folders.delete(workspace);
    }

    private static String hover(String uri, String text, String after) throws Exception {
        Hover hover = client.server().getTextDocumentService()
                .hover(new HoverParams(new TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, after)))
                .get(60, TimeUnit.SECONDS);
        return hover == null || hover.getContents() == null ? "" : hover.getContents().getRight().getValue();
    }

    @Test
    public void hoverShowsDocumentationValuesImpactsAndPorts() throws Exception {
        String property = hover(mironUri, mironText, "10 affects roqme.safe");
        assertTrue(property, property.contains("Safety of the navigation around people and obstacles."));
        String varpoint = hover(mironUri, mironText, "implies tas");
        assertTrue(varpoint, varpoint.contains("pick : main.PickDeliverCharge"));
        String sampled = hover(mironUri, mironText, "@varpoint maxVelo");
        assertTrue(sampled, sampled.contains("`100 affects roqme.mission_completion++`"));
        String literal = hover(mironUri, mironText, "implies task = task::do");
        assertTrue(literal, literal.contains("dock : main.Charge"));
        String context = hover(mironUri, mironText, "roqme.power_auto");
        assertTrue(context, context.contains("How long the robot can keep working"));

        Path bt = workspace.resolve("intralogistics.bt");
        String btText = Files.readString(bt);
        String btUri = client.open(bt, btText);
        client.awaitDiagnostics(btUri, d -> true);
        String tree = hover(btUri, btText, "<SubTreePlus ID=\"Go");
        assertTrue(tree, tree.contains("`x_input`"));
        String action = hover(btUri, btText, "<Action ID=\"objectdr");
        assertTrue(action, action.contains("obj_index"));
    }

    @Test
    public void referencesOfARoqmePropertyAreFoundInTheMiron() throws Exception {
        Path roqme = workspace.resolve("intralogistics.roqme");
        String text = Files.readString(roqme);
        String uri = client.open(roqme, text);
        client.awaitDiagnostics(uri, d -> true);
        ReferenceParams params = new ReferenceParams(new TextDocumentIdentifier(uri),
                IntralogisticsLspTest.positionAfter(text, "property saf"), new ReferenceContext(false));
        List<? extends Location> references = client.server().getTextDocumentService().references(params)
                .get(60, TimeUnit.SECONDS);
        assertTrue(references.toString(), references.stream().anyMatch(l -> l.getUri().equals(mironUri)));
    }

    @Test
    public void renameATreeFromTheMironEditsBothFiles() throws Exception {
        String text = Files.readString(workspace.resolve("intralogistics.miron"));
        String uri = client.open(workspace.resolve("intralogistics.miron"), text);
        client.awaitDiagnostics(uri, d -> true);
        WorkspaceEdit edit = client.server().getTextDocumentService().rename(new RenameParams(
                new TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, "dock : main.Cha"), "Dock"))
                .get(60, TimeUnit.SECONDS);
        Path bt = workspace.resolve("intralogistics.bt");
        String renamedTree = TextEdits.apply(Files.readString(bt), edit.getChanges().get(LspClient.uri(bt)));
        assertTrue(renamedTree.contains("<BehaviorTree ID=\"Dock\">"));
        assertFalse(renamedTree.contains("ID=\"Charge\""));
        assertTrue(renamedTree.contains("<SubTreePlus ID=\"Dock\" name=\"charge_step\"/>"));
        String renamedModel = TextEdits.apply(text, edit.getChanges().get(uri));
        assertTrue(renamedModel.contains("dock : main.Dock,"));
        // Issue 23, item 12: every edit changes something.
        java.util.Map<String, String> texts = java.util.Map.of(uri, text, LspClient.uri(bt), Files.readString(bt));
        edit.getChanges().forEach((file, edits) -> edits.forEach(e -> {
            String original = texts.get(file);
            if (original != null) {
                String replaced = original.substring(TextEdits.offset(original, e.getRange().getStart()),
                        TextEdits.offset(original, e.getRange().getEnd()));
                assertFalse(file + ": a no-op edit " + e, replaced.equals(e.getNewText()));
            }
        }));
        // The edits are not applied: the shared workspace stays as it was for the other tests.
    }

    /** Issue 23, item 12: renaming the tree GoTo in the .bt renames its uses and adds no edit that changes nothing. */
    @Test
    public void renameATreeInTheBtHasNoNoOpEdits() throws Exception {
        Path bt = workspace.resolve("intralogistics.bt");
        String text = Files.readString(bt);
        String uri = client.open(bt, text);
        client.awaitDiagnostics(uri, d -> true);
        WorkspaceEdit edit = client.server().getTextDocumentService().rename(new RenameParams(
                new TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, "<BehaviorTree ID=\"Go"), "Drive"))
                .get(60, TimeUnit.SECONDS);
        List<org.eclipse.lsp4j.TextEdit> edits = edit.getChanges().get(uri);
        for (org.eclipse.lsp4j.TextEdit e : edits) {
            String replaced = text.substring(TextEdits.offset(text, e.getRange().getStart()),
                    TextEdits.offset(text, e.getRange().getEnd()));
            assertFalse("a no-op edit " + e, replaced.equals(e.getNewText()));
        }
        String renamed = TextEdits.apply(text, edits);
        assertTrue(renamed, renamed.contains("<BehaviorTree ID=\"Drive\">"));
        assertFalse(renamed, renamed.contains("<SubTreePlus ID=\"GoTo\""));
    }

    @Test
    public void outlineListsTheDeclarations() throws Exception {
        List<Either<SymbolInformation, DocumentSymbol>> symbols = client.server().getTextDocumentService()
                .documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(mironUri))).get(60, TimeUnit.SECONDS);
        List<String> names = symbols.stream().map(s -> s.isLeft() ? s.getLeft().getName() : s.getRight().getName())
                .collect(Collectors.toList());
        assertTrue(names.toString(), names.containsAll(List.of("task", "maxVelocity", "noBattery")));
        // Issue 23, item 11: kinds that fit, so outlines and breadcrumbs have icons.
        java.util.Map<String, org.eclipse.lsp4j.SymbolKind> kinds = kinds(mironUri);
        assertEquals(kinds.toString(), org.eclipse.lsp4j.SymbolKind.Field, kinds.get("task"));
        assertEquals(kinds.toString(), org.eclipse.lsp4j.SymbolKind.Method, kinds.get("noBattery"));
        assertEquals(kinds.toString(), org.eclipse.lsp4j.SymbolKind.EnumMember, kinds.get("dock"));
        Path roqme = workspace.resolve("intralogistics.roqme");
        String roqmeUri = client.open(roqme, Files.readString(roqme));
        client.awaitDiagnostics(roqmeUri, d -> true);
        java.util.Map<String, org.eclipse.lsp4j.SymbolKind> roqmeKinds = kinds(roqmeUri);
        assertEquals(roqmeKinds.toString(), org.eclipse.lsp4j.SymbolKind.Property, roqmeKinds.get("safety"));
        assertTrue(roqmeKinds.toString(), roqmeKinds.containsValue(org.eclipse.lsp4j.SymbolKind.Event));
        assertTrue(roqmeKinds.toString(), roqmeKinds.containsValue(org.eclipse.lsp4j.SymbolKind.Variable));
        Path bt = workspace.resolve("intralogistics.bt");
        String btUri = client.open(bt, Files.readString(bt));
        client.awaitDiagnostics(btUri, d -> true);
        java.util.Map<String, org.eclipse.lsp4j.SymbolKind> btKinds = kinds(btUri);
        assertEquals(btKinds.toString(), org.eclipse.lsp4j.SymbolKind.Class, btKinds.get("Charge"));
    }

    /** The outline's symbols by their last name segment (the first of a name wins). */
    private static java.util.Map<String, org.eclipse.lsp4j.SymbolKind> kinds(String uri) throws Exception {
        java.util.Map<String, org.eclipse.lsp4j.SymbolKind> kinds = new java.util.LinkedHashMap<>();
        for (Either<SymbolInformation, DocumentSymbol> symbol : client.server().getTextDocumentService()
                .documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri))).get(60, TimeUnit.SECONDS)) {
            String name = symbol.isLeft() ? symbol.getLeft().getName() : symbol.getRight().getName();
            kinds.putIfAbsent(name.substring(name.lastIndexOf('.') + 1),
                    symbol.isLeft() ? symbol.getLeft().getKind() : symbol.getRight().getKind());
        }
        return kinds;
    }

    @Test
    public void semanticTokensOfABehaviourTreeWithTreeNodesModel() throws Exception {
        Path bt = workspace.resolve("intralogistics.bt");
        String btUri = client.open(bt, Files.readString(bt));
        client.awaitDiagnostics(btUri, d -> true);
        assertNotNull(client.server().getTextDocumentService()
                .semanticTokensFull(new SemanticTokensParams(new TextDocumentIdentifier(btUri))).get(60, TimeUnit.SECONDS));
    }

    private static List<? extends org.eclipse.lsp4j.DocumentHighlight> highlights(String uri, org.eclipse.lsp4j.Position at)
            throws Exception {
        return client.server().getTextDocumentService().documentHighlight(new org.eclipse.lsp4j.DocumentHighlightParams(
                new TextDocumentIdentifier(uri), at)).get(60, TimeUnit.SECONDS);
    }

    /** Issue 23, item 3: highlights only for the symbol under the cursor, none on keywords. */
    @Test
    public void documentHighlightsOnlyTheSymbolUnderTheCursor() throws Exception {
        assertTrue(highlights(mironUri, new org.eclipse.lsp4j.Position(0, 0)).isEmpty());
        assertTrue(highlights(mironUri, IntralogisticsLspTest.positionAfter(mironText, "@varpo")).isEmpty());
        // A varpoint: its name and its uses in the rules, each a word on one line.
        List<? extends org.eclipse.lsp4j.DocumentHighlight> task = highlights(mironUri,
                IntralogisticsLspTest.positionAfter(mironText, "@varpoint ta"));
        assertTrue(task.toString(), task.size() >= 3);
        for (org.eclipse.lsp4j.DocumentHighlight highlight : task) {
            org.eclipse.lsp4j.Range range = highlight.getRange();
            assertTrue(task.toString(), range.getStart().getLine() == range.getEnd().getLine()
                    && range.getEnd().getCharacter() - range.getStart().getCharacter() == "task".length());
        }
        Path bt = workspace.resolve("intralogistics.bt");
        String btText = Files.readString(bt);
        String btUri = client.open(bt, btText);
        client.awaitDiagnostics(btUri, d -> true);
        assertTrue(highlights(btUri, new org.eclipse.lsp4j.Position(0, 0)).isEmpty());
        assertTrue(highlights(btUri, IntralogisticsLspTest.positionAfter(btText, "<BehaviorTr")).isEmpty());
        List<? extends org.eclipse.lsp4j.DocumentHighlight> charge = highlights(btUri,
                IntralogisticsLspTest.positionAfter(btText, "<BehaviorTree ID=\"Cha"));
        assertTrue(charge.toString(), charge.size() >= 2);
        charge.forEach(h -> assertTrue(charge.toString(), h.getRange().getStart().getLine() == h.getRange().getEnd().getLine()
                && h.getRange().getEnd().getCharacter() - h.getRange().getStart().getCharacter() <= "\"Charge\"".length()));
    }

    @Test
    public void foldingRangesCoverTheTrees() throws Exception {
        Path bt = workspace.resolve("intralogistics.bt");
        String btUri = client.open(bt, Files.readString(bt));
        client.awaitDiagnostics(btUri, d -> true);
        List<FoldingRange> ranges = client.server().getTextDocumentService()
                .foldingRange(new FoldingRangeRequestParams(new TextDocumentIdentifier(btUri))).get(60, TimeUnit.SECONDS);
        assertFalse(ranges.isEmpty());
    }
}
