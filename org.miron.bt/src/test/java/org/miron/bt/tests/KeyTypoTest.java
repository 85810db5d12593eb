package org.miron.bt.tests;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.util.Suggestions;
import org.miron.bt.validation.BtIssueCodes;

/**
 * bt.key-typo (issue 30): a port reading a key nothing writes, beside a written key of a
 * near-identical name, is a warning; a key that is only read is not (the host may set it).
 */
public class KeyTypoTest {

    private static List<Issue> typos(File file) {
        return BtFiles.validate(BtFiles.load(file)).stream().filter(i -> BtIssueCodes.KEY_TYPO.equals(i.getCode()))
                .collect(Collectors.toList());
    }

    @Test
    public void aMistypedKeyIsAWarningOfferingTheWrittenKey() {
        List<Issue> typos = typos(new File(BtFiles.RESOURCES, "invalid/warn_key_typo.bt"));
        assertEquals(BtFiles.describe(typos), 3, typos.size());
        assertTrue(typos.stream().allMatch(i -> i.getSeverity() == Severity.WARNING));
        assertArrayEquals(new String[] { "target" }, typos.get(0).getData());
        assertArrayEquals(new String[] { "objekt" }, typos.get(2).getData());
    }

    @Test
    public void keysOnlyReadAreNoWarning() {
        File file = new File(BtFiles.RESOURCES, "valid/blackboard_keys_from_host.bt");
        assertEquals(List.of(), typos(file).stream().map(Issue::getMessage).collect(Collectors.toList()));
    }

    @Test
    public void theExamplesHaveNoMistypedKey() {
        for (String example : List.of("hospital-delivery/hospital.bt", "intralogistics/intralogistics.bt")) {
            File file = new File(BtFiles.repositoryRoot(), "examples/" + example);
            assertEquals(example, List.of(), typos(file).stream().map(Issue::getMessage).collect(Collectors.toList()));
        }
    }

    @Test
    public void whatCountsAsATypo() {
        assertTrue(Suggestions.isTypo("targte", "target"));
        assertTrue(Suggestions.isTypo("goal", "gaol"));
        assertTrue(Suggestions.isTypo("wards", "ward"));
        assertTrue(Suggestions.isTypo("drop_zone", "drop_zonne"));
        assertFalse("another name", Suggestions.isTypo("speed", "speed_limit"));
        assertFalse("too short to tell", Suggestions.isTypo("x", "y"));
        assertFalse("one family", Suggestions.isTypo("x_input", "y_input"));
        assertFalse("one family", Suggestions.isTypo("pose1", "pose2"));
        assertFalse("one family", Suggestions.isTypo("waypointA", "waypointB"));
        assertFalse("the same", Suggestions.isTypo("target", "target"));
    }
}
