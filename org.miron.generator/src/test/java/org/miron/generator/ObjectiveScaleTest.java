package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import org.junit.Test;

/** The objective's largest value stays within Gecode's integers for any size (docs/generators.md). */
public class ObjectiveScaleTest {
    @Test
    public void smallModelsKeepTheExactTieBreakAtTheUsualResolution() {
        ObjectiveScale s = new ObjectiveScale(2, 2); // intralogistics: maxVelocity with two properties
        assertTrue(s.lexicographic);
        assertEquals("100.0", s.unitText());
        assertEquals(7L * 20_000 + 6, s.objectiveBound());
    }

    @Test
    public void largeModelsDropTheProductButStayInRange() {
        ObjectiveScale s = new ObjectiveScale(1000, 2000); // 1 000 varpoints, two properties each
        assertFalse(s.lexicographic);
        assertEquals(20_000_000L, s.objectiveBound());
    }

    @Test
    public void theBoundFitsAtEverySize() {
        for (int n : new int[] { 1, 10, 100, 170, 200, 267, 268, 500, 1000, 100_000 }) {
            for (long tables : new long[] { n, 4L * n, 1000L * n }) {
                ObjectiveScale s = new ObjectiveScale(n, tables);
                assertTrue(n + "/" + tables, s.objectiveBound() <= ObjectiveScale.LIMIT);
                assertTrue(n + "/" + tables, s.unit > 0 && s.unit <= 100.0);
            }
        }
    }
}
