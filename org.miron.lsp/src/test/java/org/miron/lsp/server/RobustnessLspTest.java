package org.miron.lsp.server;

import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FileChangeType;
import org.eclipse.lsp4j.FileEvent;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.junit.Rule;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** Bad input never kills the server: every request still gets an answer afterwards. */
public class RobustnessLspTest {
    @Rule
    public final ExampleSession session = new ExampleSession("intralogistics");

    /** The server still answers: diagnostics of a fresh file arrive and a request returns. */
    private void assertAlive() throws Exception {
        Path probe = session.workspace.resolve("probe.roqme");
        String uri = session.client.open(probe, "roqme Probe\ncontext C : boolean\n");
        session.client.awaitDiagnostics(uri, d -> true);
        assertNotNull(session.client.server().getTextDocumentService()
                .documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri))).get(60, TimeUnit.SECONDS));
    }

    @Test
    public void malformedFiles() throws Exception {
        String bt = session.client.open(session.workspace.resolve("bad.bt"), "<root><BehaviorTree ID=\"x\"><Sequence><TreeNodesModel>\n<<<'\"");
        assertTrue(IntralogisticsLspTest.hasErrors(session.client.awaitDiagnostics(bt, IntralogisticsLspTest::hasErrors)));
        String miron = session.client.open(session.workspace.resolve("bad.miron"), "import import @varpoint ::: { } affects ++");
        session.client.awaitDiagnostics(miron, IntralogisticsLspTest::hasErrors);
        session.client.server().getTextDocumentService()
                .completion(new CompletionParams(new TextDocumentIdentifier(miron), new Position(0, 10)))
                .get(60, TimeUnit.SECONDS);
        assertAlive();
    }

    /** Navigation from a reference that resolves to nothing: no definition, and no error response. */
    @Test
    public void navigationFromBrokenReferences() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        String text = Files.readString(miron).replace("affects roqme.safety++", "affects roqme.safetyy++");
        String uri = session.client.open(miron, text);
        session.client.awaitDiagnostics(uri, IntralogisticsLspTest::hasErrors);
        TextDocumentIdentifier doc = new TextDocumentIdentifier(uri);
        Position broken = IntralogisticsLspTest.positionAfter(text, "affects roqme.safe");
        assertTrue(session.client.server().getTextDocumentService().definition(new DefinitionParams(doc, broken))
                .get(60, TimeUnit.SECONDS).getLeft().isEmpty());
        // References answer (Xtext lists the broken reference itself), hover too: no error response.
        assertNotNull(session.client.server().getTextDocumentService().references(new org.eclipse.lsp4j.ReferenceParams(doc,
                broken, new org.eclipse.lsp4j.ReferenceContext(true))).get(60, TimeUnit.SECONDS));
        session.client.server().getTextDocumentService().hover(new HoverParams(doc, broken)).get(60, TimeUnit.SECONDS);
        assertAlive();
    }

    /** Formatting a file that does not parse changes nothing (as `miron format`), without an error. */
    @Test
    public void formattingWithSyntaxErrorsLeavesTheFileAlone() throws Exception {
        String uri = session.client.open(session.workspace.resolve("broken.miron"),
                Files.readString(session.workspace.resolve("intralogistics.miron")).replaceFirst("\\{", "{{ \""));
        session.client.awaitDiagnostics(uri, IntralogisticsLspTest::hasErrors);
        assertTrue(session.client.server().getTextDocumentService().formatting(new org.eclipse.lsp4j.DocumentFormattingParams(
                new TextDocumentIdentifier(uri), new org.eclipse.lsp4j.FormattingOptions(4, true))).get(60, TimeUnit.SECONDS).isEmpty());
        assertAlive();
    }

    /** A client that sends workspace folders without announcing the capability is served on them. */
    @Test
    public void workspaceFoldersWithoutCapabilities() throws Exception {
        try (LspClient client = new LspClient()) {
            org.eclipse.lsp4j.InitializeParams params = new org.eclipse.lsp4j.InitializeParams();
            params.setWorkspaceFolders(List.of(new org.eclipse.lsp4j.WorkspaceFolder(LspClient.uri(session.workspace), "w")));
            client.server().initialize(params).get(60, TimeUnit.SECONDS);
            client.server().initialized(new org.eclipse.lsp4j.InitializedParams());
            String uri = client.open(session.workspace.resolve("intralogistics.miron"));
            // Its imports resolve: the folder's .bt and .roqme are in the workspace.
            client.awaitDiagnostics(uri, d -> !IntralogisticsLspTest.hasErrors(d));
        }
    }

    @Test
    public void hugeFile() throws Exception {
        StringBuilder text = new StringBuilder("roqme Huge\n");
        for (int i = 0; i < 5000; i++) {
            text.append("/** Context ").append(i).append(". */\ncontext C").append(i).append(" : number (0:100)\n");
        }
        String uri = session.client.open(session.workspace.resolve("huge.roqme"), text.toString());
        session.client.awaitDiagnostics(uri, d -> true);
        assertAlive();
    }

    @Test
    public void positionsOutsideTheDocument() throws Exception {
        String uri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(uri, d -> true);
        TextDocumentIdentifier doc = new TextDocumentIdentifier(uri);
        for (Position outside : List.of(new Position(5000, 3), new Position(2, 5000), new Position(-1, -1))) {
            // Empty answers, not error responses.
            assertTrue(IntralogisticsLspTest.labels(session.client.server().getTextDocumentService()
                    .completion(new CompletionParams(doc, outside)).get(60, TimeUnit.SECONDS)).isEmpty());
            session.client.server().getTextDocumentService().hover(new HoverParams(doc, outside)).get(60, TimeUnit.SECONDS);
            assertTrue(session.client.server().getTextDocumentService().definition(new DefinitionParams(doc, outside))
                    .get(60, TimeUnit.SECONDS).getLeft().isEmpty());
        }
        assertAlive();
    }

    @Test
    public void fileDeletedWhileOpen() throws Exception {
        Path bt = session.workspace.resolve("intralogistics.bt");
        String btUri = session.client.open(bt);
        String mironUri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(mironUri, d -> !IntralogisticsLspTest.hasErrors(d));
        Files.delete(bt);
        session.client.server().getWorkspaceService().didChangeWatchedFiles(new DidChangeWatchedFilesParams(
                List.of(new FileEvent(btUri, FileChangeType.Deleted))));
        settle(session.client.server().getTextDocumentService().hover(
                new HoverParams(new TextDocumentIdentifier(btUri), new Position(12, 20))));
        assertAlive();
    }

    @Test
    public void importCycle() throws Exception {
        String a = session.client.open(session.workspace.resolve("a.roqme"), "import \"b.roqme\"\nroqme A\ncontext X : boolean\n");
        String b = session.client.open(session.workspace.resolve("b.roqme"), "import \"a.roqme\"\nroqme B\ncontext Y : boolean := a.X\n");
        session.client.awaitDiagnostics(a, d -> true);
        session.client.awaitDiagnostics(b, d -> true);
        String m = session.client.open(session.workspace.resolve("c.miron"), "import \"c.miron\" as c\nimport \"a.roqme\" as a\n");
        session.client.awaitDiagnostics(m, d -> true);
        assertAlive();
    }

    @Test
    public void clientWithoutWorkspaceFolder() throws Exception {
        try (LspClient single = new LspClient()) {
            single.initializeWithoutWorkspace();
            String uri = single.open(session.workspace.resolve("intralogistics.miron"));
            single.awaitDiagnostics(uri, d -> !IntralogisticsLspTest.hasErrors(d));
        }
    }

    @Test
    public void onlyXmlFilesThatAreTreesAreBehaviourTrees() throws Exception {
        Path other = Examples.copy("intralogistics");
        try (LspClient fresh = new LspClient()) {
            Files.writeString(other.resolve("pom.xml"), "<project><modelVersion>4.0.0</modelVersion></project>\n");
            Files.writeString(other.resolve("tree.xml"), "<?xml version=\"1.0\"?>\n<root main_tree_to_execute=\"T\">"
                    + "<BehaviorTree ID=\"T\"><Inverter/></BehaviorTree></root>\n");
            fresh.initialize(other);
            String pom = fresh.open(other.resolve("pom.xml"));
            String tree = fresh.open(other.resolve("tree.xml"));
            fresh.awaitDiagnostics(tree, IntralogisticsLspTest::hasErrors);
            // Both files were opened before the tree was validated: the pom was not taken for a tree.
            assertTrue(String.valueOf(fresh.published(pom)), fresh.published(pom) == null || fresh.published(pom).isEmpty());
            assertAlive();
        } finally {
            Folders.delete(other);
        }
    }

    /** Issue 17: BehaviorTree.CPP .xml trees include each other in the editor as they do in `miron check`. */
    @Test
    public void xmlTreesIncludeXmlTrees() throws Exception {
        Path other = Examples.copy("intralogistics");
        try (LspClient fresh = new LspClient()) {
            Files.createDirectories(other.resolve("sub"));
            Files.writeString(other.resolve("sub/child.xml"), "<root main_tree_to_execute=\"Child\">"
                    + "<BehaviorTree ID=\"Child\"><AlwaysSuccess/></BehaviorTree>"
                    + "<BehaviorTree ID=\"Other\"><AlwaysSuccess/></BehaviorTree></root>\n");
            Files.writeString(other.resolve("main.xml"), "<root><include path=\"sub/child.xml\"/>"
                    + "<BehaviorTree><SubTree ID=\"Child\"/></BehaviorTree></root>\n");
            fresh.initialize(other);
            String main = fresh.open(other.resolve("main.xml"));
            fresh.awaitDiagnostics(main, d -> !IntralogisticsLspTest.hasErrors(d));
            assertTrue(String.valueOf(fresh.published(main)), fresh.published(main).isEmpty());
            String child = fresh.open(other.resolve("sub/child.xml"));
            fresh.awaitDiagnostics(child, d -> !IntralogisticsLspTest.hasErrors(d));
            assertTrue(String.valueOf(fresh.published(child)), fresh.published(child).isEmpty());
            assertAlive();
        } finally {
            Folders.delete(other);
        }
    }

    /** Waits for a request to end, with an answer or an error response: either is fine, a hang is not. */
    private static void settle(java.util.concurrent.CompletableFuture<?> request) throws Exception {
        try {
            request.get(60, TimeUnit.SECONDS);
        } catch (java.util.concurrent.ExecutionException answeredWithAnError) {
            // An error response is an answer.
        }
    }
}
