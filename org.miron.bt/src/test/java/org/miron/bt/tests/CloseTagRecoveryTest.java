package org.miron.bt.tests;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotEquals;

import java.io.File;
import java.nio.file.Files;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.validation.Issue;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.validation.BtIssueCodes;

/**
 * Issue 23, item 8: a close tag missing or naming another element is said as such for every
 * built-in, with the code and data of its quick fix, and the parser's recovery causes no further
 * errors (unknown SubTree IDs of trees it did not parse, a missing include, child counts).
 */
public class CloseTagRecoveryTest {
    @Rule
    public final TemporaryFolder temp = new TemporaryFolder();

    private static final File EXAMPLE = new File("../examples/intralogistics/intralogistics.bt");

    /** The built-ins that can hold children (or hold them in error), of both versions. */
    private static final List<String> BUILTINS = List.of("Sequence", "ReactiveSequence", "SequenceStar", "Fallback",
            "ReactiveFallback", "Parallel", "Switch2", "Switch3", "IfThenElse", "WhileDoElse", "ForceSuccess",
            "ForceFailure", "Inverter", "Repeat", "Timeout", "RetryUntilSuccessful", "KeepRunningUntilFailure", "Delay",
            "Action", "Condition", "AlwaysSuccess", "SetBlackboard", "Control", "Decorator",
            // BehaviorTree.CPP 4's (other errors of a version 3 file do not matter here: syntax only)
            "SequenceWithMemory", "AsyncSequence", "AsyncFallback", "ParallelAll", "Precondition", "RunOnce",
            "LoopInt", "LoopDouble", "LoopString", "LoopBool", "SkipUnlessUpdated", "WaitValueUpdate");

    private static List<Issue> issues(String text, File as) throws Exception {
        return BtFiles.validate(BtFiles.parse(text, as));
    }

    private static String tree(String body) {
        return "<root main_tree_to_execute=\"M\">\n  <BehaviorTree ID=\"M\">\n    " + body
                + "\n  </BehaviorTree>\n  <BehaviorTree ID=\"Other\">\n    <AlwaysSuccess/>\n  </BehaviorTree>\n</root>\n";
    }

    private static Issue onlySyntaxError(List<Issue> issues) {
        List<Issue> syntax = issues.stream().filter(Issue::isSyntaxError).collect(Collectors.toList());
        assertEquals(BtFiles.describe(issues), 1, syntax.size());
        return syntax.get(0);
    }

    @Test
    public void everyBuiltinClosedByAnotherName() throws Exception {
        for (String tag : BUILTINS) {
            String wrong = tag.equals("Fallback") ? "Sequence" : "Fallback";
            List<Issue> issues = issues(tree("<" + tag + "><AlwaysSuccess/></" + wrong + ">"),
                    new File(temp.getRoot(), "wrong.bt"));
            Issue issue = onlySyntaxError(issues);
            assertEquals(BtFiles.describe(issues), "</" + wrong + "> does not close <" + tag + ">: write </" + tag + ">",
                    issue.getMessage());
            assertEquals(BtIssueCodes.CLOSE_TAG_MISMATCH, issue.getCode());
            assertArrayEquals(new String[] { tag }, issue.getData());
        }
    }

    @Test
    public void everyBuiltinLeftOpen() throws Exception {
        for (String tag : BUILTINS) {
            String outer = tag.equals("Sequence") ? "Fallback" : "Sequence";
            List<Issue> issues = issues(tree("<" + outer + "><" + tag + "><AlwaysSuccess/></" + outer + ">"),
                    new File(temp.getRoot(), "open.bt"));
            Issue issue = onlySyntaxError(issues);
            assertEquals(BtFiles.describe(issues), "<" + tag + "> is not closed: write </" + tag + "> before </" + outer + ">",
                    issue.getMessage());
            assertEquals(BtIssueCodes.UNCLOSED_ELEMENT, issue.getCode());
            assertArrayEquals(new String[] { tag }, issue.getData());
        }
    }

    /** The example with one close tag removed: that is the one error; the trees after it are not reported unknown. */
    @Test
    public void aMissingCloseTagIsTheOnlyError() throws Exception {
        String original = Files.readString(EXAMPLE.toPath());
        File as = new File(EXAMPLE.getParentFile(), "edited.bt");
        String[][] cases = {
            { original.replaceFirst("    </Sequence>\n  </BehaviorTree>\n\n  <BehaviorTree ID=\"Deliver\">",
                    "  </BehaviorTree>\n\n  <BehaviorTree ID=\"Deliver\">"), "18:5", "Sequence", "BehaviorTree" },
            { original.replace("      </RetryUntilSuccessful>\n", ""), "33:7", "RetryUntilSuccessful", "Sequence" },
            { original.replace("      </Repeat>\n", ""), "45:7", "Repeat", "Sequence" },
            { original.replace("</Repeat>", "</Sequence>"), "44:9", "Repeat", "Sequence" },
        };
        for (String[] c : cases) {
            assertNotEquals(original, c[0]);
            List<Issue> issues = issues(c[0], as);
            assertEquals(BtFiles.describe(issues), 1, issues.size());
            Issue issue = issues.get(0);
            assertEquals(c[1], issue.getLineNumber() + ":" + issue.getColumn());
            assertEquals("<" + c[2] + "> is not closed: write </" + c[2] + "> before </" + c[3] + ">", issue.getMessage());
        }
    }

    /** A tree lost to a missing close tag and also defined next door: no "missing include" for it. */
    @Test
    public void noMissingIncludeForATreeTheErrorHid() throws Exception {
        File folder = temp.newFolder("trees");
        Files.writeString(new File(folder, "nav.bt").toPath(),
                "<root><BehaviorTree ID=\"Navigate\"><AlwaysSuccess/></BehaviorTree></root>");
        String main = "<root main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <SubTree ID=\"Navigate\"/>\n  </BehaviorTree>\n  <BehaviorTree ID=\"Dock\">\n    <Sequence>\n"
                + "      <AlwaysSuccess/>\n  </BehaviorTree>\n  <BehaviorTree ID=\"Navigate\">\n    <AlwaysSuccess/>\n"
                + "  </BehaviorTree>\n</root>\n";
        List<Issue> issues = issues(main, new File(folder, "main.bt"));
        assertEquals(BtFiles.describe(issues), 1, issues.size());
        assertEquals(BtIssueCodes.UNCLOSED_ELEMENT, issues.get(0).getCode());
        // A real unknown ID before the error is still said.
        issues = issues(main.replace("ID=\"Navigate\"/>", "ID=\"Nowhere\"/>"), new File(folder, "main.bt"));
        assertEquals(BtFiles.describe(issues), 2, issues.size());
        assertEquals(BtFiles.describe(issues), 1,
                issues.stream().filter(i -> BtIssueCodes.UNKNOWN_SUBTREE.equals(i.getCode())).count());
    }
}
