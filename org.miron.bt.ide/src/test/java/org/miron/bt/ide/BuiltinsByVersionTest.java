package org.miron.bt.ide;

import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.contentassist.ContentAssistService;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.junit.Test;

import com.google.inject.Injector;

/**
 * Completion and hover of built-in nodes follow the file's BehaviorTree.CPP version: driven
 * through Xtext's ContentAssistService and HoverService (what the language server calls for
 * textDocument/completion and textDocument/hover), on the BT language's ide injector.
 */
public class BuiltinsByVersionTest {
    private static final Injector INJECTOR = new BtIdeSetup().createInjectorAndDoEMFRegistration();
    private static final String V4 = "<root BTCPP_format=\"4\">\n";
    private static final String V3 = "<root>\n";

    private static XtextResource load(String text) throws Exception {
        XtextResourceSet set = INJECTOR.getInstance(XtextResourceSet.class);
        XtextResource resource = (XtextResource) set.createResource(URI.createFileURI("/tmp/completion-test.bt"));
        resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
        return resource;
    }

    /** The labels proposed with the caret at '|' in text. */
    private static List<String> complete(String textWithCaret) throws Exception {
        int caret = textWithCaret.indexOf('|');
        String text = textWithCaret.replace("|", "");
        Document document = new Document(1, text);
        CompletionParams params = new CompletionParams(new TextDocumentIdentifier("file:///tmp/completion-test.bt"),
                document.getPosition(caret));
        return INJECTOR.getInstance(ContentAssistService.class)
                .createCompletionList(document, load(text), params, CancelIndicator.NullImpl).getItems().stream()
                .map(CompletionItem::getLabel).toList();
    }

    private static String hover(String textWithCaret) throws Exception {
        int caret = textWithCaret.indexOf('|');
        String text = textWithCaret.replace("|", "");
        Document document = new Document(1, text);
        HoverParams params = new HoverParams(new TextDocumentIdentifier("file:///tmp/completion-test.bt"),
                document.getPosition(caret));
        Hover hover = INJECTOR.getInstance(IHoverService.class).hover(document, load(text), params,
                CancelIndicator.NullImpl);
        return hover == null || hover.getContents() == null ? "" : hover.getContents().getRight().getValue();
    }

    private static void assertHas(List<String> labels, String... expected) {
        for (String label : expected) {
            assertTrue(label + " missing in " + labels, labels.contains(label));
        }
    }

    private static void assertHasNot(List<String> labels, String... unexpected) {
        for (String label : unexpected) {
            assertFalse(label + " proposed in " + labels, labels.contains(label));
        }
    }

    private static String inTree(String root, String content) {
        return root + "<BehaviorTree ID=\"Main\">\n<Sequence>\n" + content + "\n</Sequence>\n</BehaviorTree>\n</root>\n";
    }

    @Test
    public void aVersion4FileIsOfferedVersion4Nodes() throws Exception {
        List<String> labels = complete(inTree(V4, "<|"));
        assertHas(labels, "Sequence", "SequenceWithMemory", "Script", "Sleep", "LoopInt", "Precondition",
                "RetryUntilSuccessful", "SubTree", "Action", "BehaviorTree");
        assertHasNot(labels, "SequenceStar", "SubTreePlus", "BlackboardCheckInt", "FallbackStar", "RetryUntilSuccesful");
    }

    @Test
    public void aVersion3FileIsOfferedVersion3Nodes() throws Exception {
        List<String> labels = complete(inTree(V3, "<|"));
        assertHas(labels, "Sequence", "SequenceStar", "SubTreePlus", "BlackboardCheckInt", "RetryUntilSuccessful",
                "Delay", "SubTree");
        assertHasNot(labels, "SequenceWithMemory", "Script", "Sleep", "LoopInt", "Precondition", "RetryUntilSuccesful");
    }

    @Test
    public void portsAndValuesFollowTheVersion() throws Exception {
        List<String> v4 = complete(inTree(V4, "<Parallel |><AlwaysSuccess/></Parallel>"));
        assertHas(v4, "success_count", "failure_count", "name");
        assertHasNot(v4, "success_threshold", "failure_threshold");
        List<String> v3 = complete(inTree(V3, "<Parallel |><AlwaysSuccess/></Parallel>"));
        assertHas(v3, "success_threshold", "failure_threshold");
        assertHasNot(v3, "success_count", "failure_count");
        assertHas(complete(inTree(V4, "<SubTree ID=\"Main\" |/>")), "_autoremap");
        assertHasNot(complete(inTree(V4, "<SubTree ID=\"Main\" |/>")), "__shared_blackboard");
        assertHas(complete(inTree(V4, "<Precondition if=\"true\" else=\"|\"><AlwaysSuccess/></Precondition>")),
                "FAILURE", "SKIPPED");
        assertHas(complete(inTree(V4, "<LoopInt queue=\"1;2\" if_empty=\"|\"><AlwaysSuccess/></LoopInt>")), "SKIPPED");
    }

    @Test
    public void hoverDescribesABuiltinFromTheCatalogue() throws Exception {
        String repeat = hover(inTree(V3, "<Rep|eat num_cycles=\"2\"><AlwaysSuccess/></Repeat>"));
        assertNotNull(repeat);
        assertTrue(repeat, repeat.contains("**Repeat**") && repeat.contains("`num_cycles` (input, int, required)")
                && repeat.contains("Use -1 to create an infinite loop."));
        String parallel = hover(inTree(V4, "<Para|llel success_count=\"1\"><AlwaysSuccess/></Parallel>"));
        assertTrue(parallel, parallel.contains("`failure_count` (input, int, default 1)")
                && !parallel.contains("success_threshold"));
    }
}
