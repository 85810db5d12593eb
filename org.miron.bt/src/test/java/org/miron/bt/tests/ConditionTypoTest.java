package org.miron.bt.tests;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.validation.BtIssueCodes;

/**
 * bt.condition-typo (issue 36, item 6): BehaviorTree.CPP 4 ignores an attribute it does not know,
 * so a mistyped pre/post-condition disables its script without a word; miron check warns at the
 * attribute's name with the condition meant.
 */
public class ConditionTypoTest {
    private static final File AS = new File(BtFiles.RESOURCES, "valid/condition_typo.bt");

    private static List<Issue> typos(String text) throws Exception {
        return BtFiles.validate(BtFiles.parse(text, AS)).stream()
                .filter(i -> BtIssueCodes.CONDITION_TYPO.equals(i.getCode())).collect(Collectors.toList());
    }

    private static String tree(String format, String body) {
        return "<root" + format + " main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n" + body
                + "  </BehaviorTree>\n</root>\n";
    }

    @Test
    public void aMistypedConditionIsAWarningAtItsNameWithTheIntendedName() throws Exception {
        List<Issue> typos = typos(tree(" BTCPP_format=\"4\"", "    <Sequence>\n"
                + "      <AlwaysSuccess _onSucess=\"done := true\"/>\n"
                + "      <AlwaysSuccess   _skipif=\"done\"/>\n"
                + "    </Sequence>\n"));
        assertEquals(BtFiles.describe(typos), 2, typos.size());
        assertEquals("4:22", typos.get(0).getLineNumber() + ":" + typos.get(0).getColumn());
        assertEquals(Severity.WARNING, typos.get(0).getSeverity());
        assertEquals("BehaviorTree.CPP 4 ignores attribute '_onSucess', no pre/post-condition: did you mean '_onSuccess'?",
                typos.get(0).getMessage());
        assertArrayEquals(new String[] { "_onSuccess" }, typos.get(0).getData());
        assertEquals("5:24", typos.get(1).getLineNumber() + ":" + typos.get(1).getColumn());
        assertArrayEquals(new String[] { "_skipIf" }, typos.get(1).getData());
    }

    @Test
    public void knownNamesOtherNamesAndVersionThreeAreNoWarning() throws Exception {
        assertEquals(List.of(), typos(tree(" BTCPP_format=\"4\"", "    <Sequence>\n"
                + "      <AlwaysSuccess _onSuccess=\"done := true\" _skipIf=\"done\" _description=\"d\" _uid=\"3\"/>\n"
                + "      <AlwaysSuccess _private_note=\"x\"/>\n"
                + "    </Sequence>\n")).stream().map(Issue::getMessage).collect(Collectors.toList()));
        assertEquals("version 3 knows no conditions: bt.v4-only-attribute's", List.of(),
                typos(tree("", "    <AlwaysSuccess _onSucess=\"x\"/>\n")).stream().map(Issue::getMessage).collect(Collectors.toList()));
    }
}
