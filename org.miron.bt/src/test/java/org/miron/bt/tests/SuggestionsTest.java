package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;

import java.util.List;

import org.junit.Test;
import org.miron.bt.util.Suggestions;

/** "Did you mean" candidates: typos are found, other names are not. */
public class SuggestionsTest {

    @Test
    public void aSwapOfTwoLettersIsOneEdit() {
        assertEquals(List.of("Main"), Suggestions.closest("Mian", List.of("Main", "Dock")));
    }

    @Test
    public void nearestComeFirstAndCaseCountsLess() {
        assertEquals(List.of("navigate", "Navigator"),
                Suggestions.closest("Navigate", List.of("Navigator", "navigate", "Dock", "Navigate")));
    }

    @Test
    public void theQualifierDoesNotWidenTheTolerance() {
        assertEquals(List.of("Base.battery"),
                Suggestions.closest("Base.batery", List.of("Base.safety", "Base.battery", "Other.battery")));
    }

    @Test
    public void shortNamesAllowOneEditAndAtMostThreeAreGiven() {
        assertEquals(List.of(), Suggestions.closest("Nope", List.of("Nav", "Main")));
        assertEquals(3, Suggestions.closest("abcdefghij", List.of("abcdefghiX", "abcdefghXj", "abcdefgXij",
                "abcdefXhij")).size());
    }
}
