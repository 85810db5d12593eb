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
    private static org.eclipse.lsp4j.SemanticTokensLegend legend;

    @BeforeClass
    public static void setUp() throws Exception {
        workspace = Examples.copy("intralogistics");
        client = new LspClient();
        legend = client.initialize(workspace).getCapabilities().getSemanticTokensProvider().getLegend();
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
        // requirements are listed as rules are, with a kind of their own
        assertTrue(names.toString(), names.containsAll(List.of("docksOnLowBattery", "neverStranded", "slowNearPeople",
                "rarelyStranded")));
        assertEquals(kinds.toString(), org.eclipse.lsp4j.SymbolKind.Interface, kinds.get("docksOnLowBattery"));
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

    /** The semantic tokens of a file: "line:column text" → "type[ modifier...]". */
    private static java.util.Map<String, String> tokens(String uri, String text) throws Exception {
        List<Integer> data = client.server().getTextDocumentService()
                .semanticTokensFull(new SemanticTokensParams(new TextDocumentIdentifier(uri))).get(60, TimeUnit.SECONDS).getData();
        java.util.Map<String, String> tokens = new java.util.LinkedHashMap<>();
        String[] lines = text.split("\n", -1);
        int line = 0;
        int column = 0;
        for (int i = 0; i + 4 < data.size() + 1; i += 5) {
            line += data.get(i);
            column = data.get(i) == 0 ? column + data.get(i + 1) : data.get(i + 1);
            String word = lines[line].substring(column, column + data.get(i + 2));
            StringBuilder kind = new StringBuilder(legend.getTokenTypes().get(data.get(i + 3)));
            for (int bit = 0; bit < legend.getTokenModifiers().size(); bit++) {
                if ((data.get(i + 4) & (1 << bit)) != 0) {
                    kind.append(' ').append(legend.getTokenModifiers().get(bit));
                }
            }
            tokens.put((line + 1) + ":" + word, kind.toString());
        }
        return tokens;
    }

    /** The type of the first token with this text on the first line that contains the context. */
    private static String tokenType(java.util.Map<String, String> tokens, String text, String context, String word) {
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].contains(context)) {
                return tokens.get((i + 1) + ":" + word);
            }
        }
        throw new AssertionError("no line with " + context);
    }

    /** Issue 23, item 15 (the server's half): names coloured by what they denote, BT elements by kind. */
    @Test
    public void semanticTokensSayWhatNamesDenote() throws Exception {
        // Other tests of the class open the file as it is on disk: this one needs the extra rule back.
        client.open(workspace.resolve("intralogistics.miron"), mironText);
        client.awaitDiagnostics(mironUri, d -> true);
        java.util.Map<String, String> miron = tokens(mironUri, mironText);
        assertEquals(miron.toString(), "namespace", tokenType(miron, mironText, "dock : main.Charge", "main"));
        assertEquals(miron.toString(), "class", tokenType(miron, mironText, "dock : main.Charge", "Charge"));
        assertEquals(miron.toString(), "property", tokenType(miron, mironText, "rule r2 : roqme.safety", "safety"));
        assertEquals(miron.toString(), "property", tokenType(miron, mironText, "10 affects roqme.safety", "safety"));
        assertEquals(miron.toString(), "enumMember", tokenType(miron, mironText, "implies task = task::dock", "dock"));
        assertEquals(miron.toString(), "variable declaration", tokenType(miron, mironText, "@varpoint task", "task"));
        assertEquals(miron.toString(), "class", tokenType(miron, mironText, "} in main.PickDeliverChargeSubtree",
                "PickDeliverChargeSubtree"));

        Path bt = workspace.resolve("intralogistics.bt");
        String btText = Files.readString(bt);
        String btUri = client.open(bt, btText);
        client.awaitDiagnostics(btUri, d -> true);
        java.util.Map<String, String> tree = tokens(btUri, btText);
        assertEquals(tree.toString(), "class declaration", tokenType(tree, btText, "<BehaviorTree ID=\"Charge\"", "Charge"));
        assertEquals(tree.toString(), "class", tokenType(tree, btText, "<SubTreePlus ID=\"GoTo\"", "GoTo"));
        assertEquals(tree.toString(), "keyword", tokenType(tree, btText, "<Sequence name=\"Charge\"", "Sequence"));
        assertEquals(tree.toString(), "keyword", tokenType(tree, btText, "</Sequence>", "Sequence"));
        assertEquals(tree.toString(), "function", tokenType(tree, btText, "<Action ID=\"objectdrop\"", "Action"));
        assertEquals(tree.toString(), "class", tokenType(tree, btText, "<SubTreePlus ID=\"GoTo\"", "SubTreePlus"));
        assertEquals(tree.toString(), "decorator", tokenType(tree, btText, "<RetryUntilSuccessful", "RetryUntilSuccessful"));
        java.util.Set<String> kinds = new java.util.HashSet<>(tree.values());
        assertTrue(kinds.toString(), kinds.containsAll(List.of("keyword", "function", "class", "property")));
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
