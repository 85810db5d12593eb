package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import org.junit.Test;
import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ast.Assignment;
import org.miron.bt.script.ast.AssignmentOperator;
import org.miron.bt.script.ast.Binary;
import org.miron.bt.script.ast.BinaryOperator;
import org.miron.bt.script.ast.BooleanLiteral;
import org.miron.bt.script.ast.Comparison;
import org.miron.bt.script.ast.ComparisonOperator;
import org.miron.bt.script.ast.Conditional;
import org.miron.bt.script.ast.Name;
import org.miron.bt.script.ast.NumberLiteral;
import org.miron.bt.script.ast.Parenthesized;
import org.miron.bt.script.ast.StringLiteral;
import org.miron.bt.script.ast.Unary;
import org.miron.bt.script.ast.UnaryOperator;

/** The scripting language's parser on BehaviorTree.CPP 4 scripts: structure, precedence, errors. */
public class ScriptParserTest {

    private static ParsedScript ok(String text) {
        ParsedScript parsed = BtScripts.parse(text);
        assertFalse(text + ": " + parsed.getErrors(), parsed.hasErrors());
        return parsed;
    }

    @Test
    public void statementsAreSeparatedBySemicolons() {
        ParsedScript parsed = ok("a := 1; b = 'two' ;c += 0x1F");
        assertEquals(3, parsed.getScript().getStatements().size());
        Assignment first = (Assignment) parsed.getScript().getStatements().get(0);
        assertEquals(AssignmentOperator.ASSIGN_CREATE, first.getOperator());
        assertEquals("a", ((Name) first.getTarget()).getName());
        assertEquals(1.0, ((NumberLiteral) first.getValue()).value(), 0);
        Assignment second = (Assignment) parsed.getScript().getStatements().get(1);
        assertEquals(AssignmentOperator.ASSIGN_EXISTING, second.getOperator());
        assertEquals("two", ((StringLiteral) second.getValue()).getValue());
        assertEquals(31.0, ((NumberLiteral) ((Assignment) parsed.getScript().getStatements().get(2)).getValue()).value(), 0);
    }

    @Test
    public void productBindsTighterThanSum() {
        Binary sum = (Binary) ok("1 + 2 * 3").getScript().getStatements().get(0);
        assertEquals(BinaryOperator.PLUS, sum.getOperator());
        assertEquals(BinaryOperator.TIMES, ((Binary) sum.getRight()).getOperator());
    }

    @Test
    public void andAndOrShareOneLevelLeftToRight() {
        // BT.CPP: a || b && c is (a || b) && c.
        Binary and = (Binary) ok("a || b && c").getScript().getStatements().get(0);
        assertEquals(BinaryOperator.LOGIC_AND, and.getOperator());
        assertEquals(BinaryOperator.LOGIC_OR, ((Binary) and.getLeft()).getOperator());
    }

    @Test
    public void comparisonsChain() {
        Comparison chain = (Comparison) ok("1 < x <= 3").getScript().getStatements().get(0);
        assertEquals(3, chain.getOperands().size());
        assertEquals(ComparisonOperator.LESS, chain.getOperators().get(0));
        assertEquals(ComparisonOperator.LESS_EQUAL, chain.getOperators().get(1));
    }

    @Test
    public void conditionalAssignmentAndConcat() {
        Assignment assignment = (Assignment) ok("msg := ok ? 'yes' .. name : (-1.5e2)").getScript().getStatements().get(0);
        Conditional conditional = (Conditional) assignment.getValue();
        assertEquals(BinaryOperator.CONCAT, ((Binary) conditional.getThen()).getOperator());
        Unary negate = (Unary) ((Parenthesized) conditional.getElse()).getExpression();
        assertEquals(UnaryOperator.NEGATE, negate.getOperator());
        assertTrue(((NumberLiteral) negate.getOperand()).isReal());
    }

    @Test
    public void booleansNotAndBitwise() {
        Binary and = (Binary) ok("!done & ~mask | true").getScript().getStatements().get(0);
        assertEquals(BinaryOperator.BIT_OR, and.getOperator());
        assertTrue(((BooleanLiteral) and.getRight()).isValue());
        assertEquals(UnaryOperator.LOGICAL_NOT, ((Unary) ((Binary) and.getLeft()).getLeft()).getOperator());
    }

    @Test
    public void rootBlackboardKeysAndEnums() {
        ok("@battery < LOW_LEVEL; state == RUNNING_STATE");
    }

    @Test
    public void emptyScriptHasNoStatements() {
        assertTrue(ok("").getScript().getStatements().isEmpty());
        assertTrue(ok("  ").getScript().getStatements().isEmpty());
    }

    @Test
    public void syntaxErrorsHaveOffsets() {
        ParsedScript parsed = BtScripts.parse("a := 1; b := a +");
        assertTrue(parsed.hasErrors());
        // At the end of input Xtext reports on the last token, the dangling +.
        assertEquals(15, parsed.getErrors().get(0).getOffset());
        ParsedScript equalsTwice = BtScripts.parse("x = = 1");
        assertEquals(4, equalsTwice.getErrors().get(0).getOffset());
    }

    @Test
    public void assignmentIsNotAssociative() {
        assertTrue(BtScripts.parse("a = b = 1").hasErrors());
    }

    @Test
    public void trailingAndEmptyStatementsAreErrors() {
        assertTrue(BtScripts.parse("a := 1;").hasErrors());
        assertTrue(BtScripts.parse("a := 1;; b := 2").hasErrors());
        assertTrue(BtScripts.parse("a := b\nc := 2").hasErrors());
    }

    @Test
    public void numbersWithSuffixesAreErrorsAtTheSuffix() {
        assertEquals(6, BtScripts.parse("a := 1..2").getErrors().get(0).getOffset());
        assertEquals(7, BtScripts.parse("a := 12abc").getErrors().get(0).getOffset());
        assertEquals("invalid suffix on number literal", BtScripts.parse("a := 5.").getErrors().get(0).getMessage());
        ok("a := '1..2'; b := x1 == 1.5e3; c := 1 .. 2");
    }

    @Test
    public void operatorGroupsDoNotMixWithoutParentheses() {
        assertEquals(11, BtScripts.parse("a := 1 + 2 & 3").getErrors().get(0).getOffset());
        assertTrue(BtScripts.parse("a := ~b + 1").hasErrors());
        assertTrue(BtScripts.parse("a := !-1").hasErrors());
        ok("a := (1 + 2) & 3; b := - - c; d := !!e; f := 1 | 2 ^ 3; g := !h & i; j := 'a' .. 'b' .. 1");
    }
}
