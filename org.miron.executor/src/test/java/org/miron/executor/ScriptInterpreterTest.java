package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.Map;
import java.util.Optional;

import org.junit.Test;
import org.miron.executor.scripting.ScriptCompiler;
import org.miron.executor.scripting.ScriptException;
import org.miron.executor.scripting.ScriptScope;
import org.miron.executor.scripting.ScriptValues;

/**
 * The version-4 scripting language on a blackboard: parsed once by {@link ScriptCompiler}, run
 * with BT.CPP 4's value rules (the oracle tests compare the same rules with the real library).
 */
public class ScriptInterpreterTest {
    private final Blackboard board = Blackboard.create();
    private Map<String, Integer> enums = Map.of();

    private Object run(String script) {
        return ScriptCompiler.compile(script).run(new ScriptScope(board, enums));
    }

    private String text(String key) {
        return board.get(key).map(ScriptValues::of).map(ScriptValues::toText).orElse(null);
    }

    private void assertFails(String script, String messagePart) {
        try {
            run(script);
            fail(script + " should fail");
        } catch (ScriptException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains(messagePart));
        }
    }

    @Test
    public void colonEqualsCreatesAnEntryEqualsNeedsOne() {
        assertFails("speed = 2", ":=");
        assertFalse(board.contains("speed"));
        run("speed := 2");
        run("speed = 3");
        assertEquals(Optional.of(3L), board.get("speed"));
    }

    @Test
    public void anEntryDeclaredByAPortCanBeAssignedWithEquals() {
        board.declare("goal");
        assertFails("x := goal", "no value");
        run("goal = 'dock'");
        assertEquals("dock", text("goal"));
    }

    @Test
    public void arithmeticYieldsRealsAndIntegersStayIntegersWhenAssignedBack() {
        run("i := 1; i += 1; r := 7 / 2; neg := -1");
        assertEquals(Optional.of(2L), board.get("i"));
        assertEquals(Optional.of(3.5), board.get("r"));
        assertEquals("-1.000000", text("neg"));
        assertFails("i += 0.5", "not an integer");
        assertFails("i = 2.5", "not an integer");
    }

    @Test
    public void textJoinsWithDotDotAndIsReadAsANumberWhenComparedWithOne() {
        run("n := 2; s := 'v' .. n .. '/' .. 1.5; t := 'a' + 'b'");
        assertEquals("v2/1.500000", text("s"));
        assertEquals("ab", text("t"));
        assertEquals(1.0, run("'3' == 3"));
        assertEquals(1.0, run("'true' == 1"));
        assertFails("x := 1 + 'a'", "not permitted");
        assertFails("x := 'a' == 1", "not a number");
    }

    @Test
    public void comparisonsChainAndRealsCompareWithFloatEpsilon() {
        assertEquals(1.0, run("1 < 2 <= 2 != 3"));
        assertEquals(0.0, run("1 < 2 > 3"));
        assertEquals(1.0, run("0.1 + 0.2 == 0.3"));
        assertEquals(1.0, run("'abc' < 'abd'"));
    }

    @Test
    public void logicEvaluatesBothSidesAndNeedsBooleans() {
        run("done := 0");
        assertEquals(0.0, run("false && (done := 1)"));
        assertEquals("both sides of && run, as in BT.CPP", Optional.of(1L), board.get("done"));
        assertFails("x := true && 2", "castable to bool");
        assertEquals(1.0, run("!0"));
    }

    @Test
    public void bitwiseNeedsIntegers() {
        assertEquals(1.0, run("5 & 3"));
        assertEquals(5.0, run("6 ^ 3"));
        assertEquals(-6.0, run("~5"));
        assertFails("x := 1.5 | 1", "not an integer");
    }

    @Test
    public void ternaryPicksABranchAndOnlyRunsThatOne() {
        run("a := 0; b := 0");
        run("1 > 0 ? (a := 5) : (b := 5)");
        assertEquals(Optional.of(5L), board.get("a"));
        assertEquals(Optional.of(0L), board.get("b"));
    }

    @Test
    public void enumNamesAreNumbersAndWinOverKeys() {
        enums = Map.of("RED", 1, "GREEN", 2);
        run("color := GREEN; RED := 7");
        assertEquals(Optional.of(2.0), board.get("color"));
        assertEquals(1.0, run("color == 'GREEN'"));
        assertEquals("the enum, not the entry named RED", 1.0, run("RED == 1"));
    }

    @Test
    public void atKeyIsTheRootBlackboards() {
        Blackboard child = board.createChild();
        ScriptCompiler.compile("@mission := 'deliver'; local := 1").run(new ScriptScope(child, enums));
        assertEquals("deliver", text("mission"));
        assertFalse(board.contains("local"));
    }

    @Test
    public void unknownKeysAndValuesOfJavaActionsAreReadLikeBtCpp() {
        assertFails("x := y", "Variable not found: y");
        board.set("flag", true);
        board.set("count", 3);
        assertEquals(1.0, run("flag == 1 && count == 3"));
    }

    @Test
    public void aSyntaxErrorIsReportedWhenCompilingWithItsColumn() {
        try {
            ScriptCompiler.compile("a := 1 +");
            fail();
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("column"));
        }
        try {
            ScriptCompiler.compile("   ");
            fail();
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("empty"));
        }
    }

    @Test
    public void conditionsAcceptRealsAndZeroOrOneOnly() {
        assertTrue(ScriptValues.toBoolean(2.5));
        assertFalse(ScriptValues.toBoolean(0L));
        try {
            ScriptValues.toBoolean(2L);
            fail("an integer other than 0 or 1 is not a boolean in BT.CPP 4");
        } catch (ScriptException expected) {
            // as BT.CPP's "Implicit casting to bool is not allowed"
        }
        try {
            ScriptValues.toBoolean("true");
            fail("text is not a condition");
        } catch (ScriptException expected) {
            // as BT.CPP's "no known safe conversion"
        }
    }
}
