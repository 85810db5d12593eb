package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/** Completion in the three languages, on unsaved buffers of the intralogistics example. */
public class CompletionLspTest {
    private static Path workspace;
    private static LspClient client;

    @BeforeClass
    public static void setUp() throws Exception {
        workspace = Examples.copy("intralogistics");
        client = new LspClient();
        client.initialize(workspace);
    }

    @AfterClass
    public static void tearDown() throws Exception {
        client.close();
        Folders.delete(workspace);
    }

    /** Labels proposed when the buffer of a file is `text`, the caret just after `after`. */
    private static List<String> complete(String file, String text, String after) throws Exception {
        Path path = workspace.resolve(file);
        String uri = client.open(path, text);
        client.awaitDiagnostics(uri, d -> true);
        try {
            return IntralogisticsLspTest.labels(client.server().getTextDocumentService()
                    .completion(new CompletionParams(new TextDocumentIdentifier(uri),
                            IntralogisticsLspTest.positionAfter(text, after)))
                    .get(60, TimeUnit.SECONDS));
        } finally {
            client.server().getTextDocumentService().didClose(
                    new org.eclipse.lsp4j.DidCloseTextDocumentParams(new TextDocumentIdentifier(uri)));
            client.forget(uri);
        }
    }

    private static String example(String file) throws Exception {
        return Files.readString(workspace.resolve(file));
    }

    private static void assertHas(List<String> labels, String... expected) {
        for (String label : expected) {
            assertTrue(label + " missing in " + labels, labels.contains(label));
        }
    }

    @Test
    public void mironAliasesEnumLiteralsPresetAndImpacts() throws Exception {
        String text = example("intralogistics.miron") + "\nrule r2 : roqme.safety < 0.3 implies task = task::\n";
        assertHas(complete("intralogistics.miron", text, "task = task::"), "task::dock", "task::pick");
        assertHas(complete("intralogistics.miron", text, "pickDeliverCharge : "), "preset", "main.Charge");
        assertHas(complete("intralogistics.miron", text, "10 affects roqme."), "roqme.safety", "roqme.mission_completion");
        List<String> impact = complete("intralogistics.miron", text, "100 affects ");
        assertHas(impact, "roqme", "roqme.safety");
        assertFalse("main leads to no property: " + impact, impact.contains("main"));
        assertHas(complete("intralogistics.miron", text, "10 affects roqme.safety"), "++", "---");
        List<String> condition = complete("intralogistics.miron", text, "rule r2 : ");
        assertHas(condition, "roqme", "roqme.BatteryLevel", "roqme.safety", "roqme::AvailableSpace::HIGH", "maxVelocity", "avg");
        assertHas(complete("intralogistics.miron", text, "} in main."), "main.PickDeliverChargeSubtree");
    }

    @Test
    public void requirementKeywordsAndNames() throws Exception {
        String text = example("intralogistics.miron") + "\nrequirement r2 : always (roqme.safety < 0.3 implies "
                + "eventually within 5 seconds task = task::dock) with probability >= 0.9\n";
        assertHas(complete("intralogistics.miron", text, "r2 : "), "always", "never", "eventually", "roqme",
                "roqme.BatteryLevel", "maxVelocity");
        // the same names after the alias as in a rule
        List<String> afterAlias = complete("intralogistics.miron", text, "r2 : always (roqme.");
        assertHas(afterAlias, "roqme.BatteryLevel", "roqme.safety", "roqme.Docked");
        assertHas(complete("intralogistics.miron", text, "implies eventually "), "within");
        // the bound's units, and a varpoint's values, as RoQME and rules write them
        assertHas(complete("intralogistics.miron", text, "eventually within 5 "), "milliseconds", "seconds", "minutes",
                "hours");
        assertHas(complete("intralogistics.miron", text, "5 seconds task = "), "task::dock");
        assertHas(complete("intralogistics.miron", text, "task = task::dock) "), "with", "implies");
        assertHas(complete("intralogistics.miron", text, "task::dock) with "), "probability");
        assertHas(complete("intralogistics.miron", text, "with probability "), ">=");
        assertHas(complete("intralogistics.miron", text, "with probability >= 0.9\n"), "requirement", "rule");
    }

    @Test
    public void proposalsCarryTheDocumentationComment() throws Exception {
        String text = example("intralogistics.miron");
        Path path = workspace.resolve("intralogistics.miron");
        String uri = client.open(path, text);
        client.awaitDiagnostics(uri, d -> true);
        try {
            Either<List<CompletionItem>, CompletionList> result = client.server().getTextDocumentService()
                    .completion(new CompletionParams(new TextDocumentIdentifier(uri),
                            IntralogisticsLspTest.positionAfter(text, "10 affects roqme.")))
                    .get(60, TimeUnit.SECONDS);
            CompletionItem safety = result.getRight().getItems().stream().filter(i -> i.getLabel().equals("roqme.safety"))
                    .findFirst().get();
            assertEquals("Safety of the navigation around people and obstacles.", safety.getDocumentation().getLeft());
        } finally {
            client.server().getTextDocumentService().didClose(
                    new org.eclipse.lsp4j.DidCloseTextDocumentParams(new TextDocumentIdentifier(uri)));
        }
    }

    @Test
    public void roqmeNamesFunctionsAndKeywords() throws Exception {
        String text = example("intralogistics.roqme");
        List<String> expression = complete("intralogistics.roqme", text, "var recentDeliveries : number := ");
        assertHas(expression, "DeliveryDone", "safety", "count", "avg", "AvailableSpace::HIGH");
        assertHas(complete("intralogistics.roqme", text, "property safety "), "context", "property", "reference");
    }

    @Test
    public void btNodeIdsSubtreesAndAttributes() throws Exception {
        String text = example("intralogistics.bt");
        String drop = "<Action ID=\"objectdrop\" obj_index=\"-1\"/>";
        List<String> element = complete("intralogistics.bt", text.replace(drop, drop + "\n<"), drop + "\n<");
        assertHas(element, "Sequence", "RetryUntilSuccessful", "MoveTo", "objectpick", "GoTo");
        assertEquals("GoTo is a tree and a declared SubTree: proposed once", 1,
                element.stream().filter("GoTo"::equals).count());
        assertHas(complete("intralogistics.bt", text.replace(drop, drop + "\n<Action ID=\"\"/>"), "\n<Action ID=\""),
                "MoveTo", "objectdrop");
        assertHas(complete("intralogistics.bt", text.replace(drop, drop + "\n<SubTree ID=\"\"/>"), "\n<SubTree ID=\""),
                "Charge", "GoTo");
        List<String> ports = complete("intralogistics.bt", text.replace(drop, "<Action ID=\"MoveTo\" />"), "<Action ID=\"MoveTo\" ");
        assertHas(ports, "x", "y", "name");
        assertHas(complete("intralogistics.bt", text.replace(drop, "<MoveTo x=\"1\" />"), "<MoveTo x=\"1\" "), "y");
        List<String> repeat = complete("intralogistics.bt", text.replace(drop, "<Repeat num_cycles=\"2\" ></Repeat>"),
                "<Repeat num_cycles=\"2\" ");
        assertFalse(repeat.toString(), repeat.contains("num_cycles"));
        assertHas(complete("intralogistics.bt", text.replace("main_tree_to_execute=\"Main\"", "main_tree_to_execute=\"\""),
                "main_tree_to_execute=\""), "Main", "Charge");
        assertHas(complete("intralogistics.bt", text, "__shared_blackboard=\""), "true", "false");
    }

    @Test
    public void btCompletionWorksAfterTheTreeNodesModel() throws Exception {
        String text = example("intralogistics.bt").replace("</root>",
                "<BehaviorTree ID=\"Late\">\n<Timeout ></Timeout>\n</BehaviorTree>\n</root>");
        // ">" and "/>" come from the content-assist parser, which must have seen one TreeNodesModel token.
        assertHas(complete("intralogistics.bt", text, "<Timeout "), "msec", ">", "/>");
        String late = example("intralogistics.bt").replace("</root>", "<BehaviorTree ID=\"Late\">\n<\n</BehaviorTree>\n</root>");
        assertHas(complete("intralogistics.bt", late, "\"Late\">\n<"), "Timeout", "TreeNodesModel", "MoveTo");
    }

    private static void assertLacks(List<String> labels, String... unexpected) {
        for (String label : unexpected) {
            assertFalse(label + " proposed in " + labels, labels.contains(label));
        }
    }

    /** Issue 23, item 6: after `task::` only the literals, no operators. */
    @Test
    public void onlyWhatCanFollowAfterAnEnumType() throws Exception {
        String text = example("intralogistics.miron") + "\nrule r2 : roqme.safety < 0.3 implies task = task::\n";
        List<String> labels = complete("intralogistics.miron", text, "task = task::");
        assertHas(labels, "task::dock");
        assertLacks(labels, "&", "'", "*", "+", "-", "->", "|", "(", "<", "=");
    }

    /** Issue 23, items 6 and 7: in a version-4 file, after `<`, the version's elements only, no `<` or `</`. */
    @Test
    public void version4ElementsAndAttributesOnly() throws Exception {
        String text = "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence>\n      <\n      <SubTree ID=\"GoTo\" />\n    </Sequence>\n  </BehaviorTree>\n"
                + "  <BehaviorTree ID=\"GoTo\">\n    <AlwaysSuccess/>\n  </BehaviorTree>\n</root>\n";
        List<String> elements = complete("v4.bt", text, "<Sequence>\n      <");
        assertHas(elements, "SequenceWithMemory", "Script", "Fallback", "GoTo");
        assertLacks(elements, "<", "</", "SequenceStar", "FallbackStar", "SubTreePlus", "BlackboardCheckInt",
                "BlackboardCheckDouble", "BlackboardCheckString", "RetryUntilSuccesful");
        assertFalse(elements.toString(), elements.get(0).startsWith("<"));
        List<String> attributes = complete("v4.bt", text, "<SubTree ID=\"GoTo\" ");
        assertHas(attributes, "_autoremap", "/>");
        assertLacks(attributes, "ID", "__shared_blackboard");
    }
}
