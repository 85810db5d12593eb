package org.miron.runtime.requirement;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.miron.runtime.requirement.Traces.always;
import static org.miron.runtime.requirement.Traces.eventually;
import static org.miron.runtime.requirement.Traces.implies;
import static org.miron.runtime.requirement.Traces.is;
import static org.miron.runtime.requirement.Traces.modeIs;
import static org.miron.runtime.requirement.Traces.op;
import static org.miron.runtime.requirement.Traces.temporal;
import static org.miron.runtime.requirement.Traces.x;

import com.fasterxml.jackson.databind.node.TextNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.Test;

/** Each operator on hand-made traces, with their boundary cases. */
public class RequirementMonitorsTest {
    @Test
    public void alwaysTellsEachViolationAtItsInstantWithTheValuesThenAndWhenItIsMetAgain() {
        List<RequirementEvent> events = new ArrayList<>();
        RequirementMonitors m = Traces.monitors(always(x("<", 5))).onEvent(events::add);
        m.context(0, "x", 1.0);
        m.context(1000, "x", 7.0);
        m.context(3000, "x", 2.0);
        m.context(4000, "x", 9.5);
        RequirementResult r = m.finish(5000).get(0);
        assertEquals(Verdict.VIOLATED, r.verdict());
        assertEquals(2, r.violations());
        assertEquals(1000, r.firstViolation().timeMs());
        assertEquals(Map.of("x", 7.0), r.firstViolation().values());
        assertEquals(List.of("violated@1000", "met@3000", "violated@4000"),
                events.stream().map(e -> e.verdict() + "@" + e.timeMs()).toList());
        assertEquals("r0 violated: x = 7.0", events.get(0).describe());
    }

    @Test
    public void neverIsAlwaysNot() {
        RequirementMonitors m = Traces.monitors(temporal("never", null, x(">", 5)), temporal("never", null, x(">", 50)));
        m.context(0, "x", 1.0);
        m.context(10, "x", 6.0);
        List<RequirementResult> r = m.finish(20);
        assertEquals(List.of("violated", "holds"), Traces.verdicts(r));
        assertEquals(10, r.get(0).firstViolation().timeMs());
    }

    @Test
    public void aDeadlineIsInclusiveAndTheViolationIsAtTheInstantTheObligationOpened() {
        // a at 1000; b must follow within 500 ms: at 1500 exactly is in time, at 1501 is late
        for (long bAt : new long[] {1500, 1501}) {
            RequirementMonitors m = Traces.monitors(always(implies(is("a"), eventually(500, is("b")))));
            m.context(0, "a", false);
            m.context(0, "b", false);
            m.context(1000, "a", true);
            m.context(1000, "b", false);
            m.context(1200, "a", false);
            m.context(bAt, "b", true);
            RequirementResult r = m.finish(5000).get(0);
            if (bAt == 1500) {
                assertEquals(Verdict.HOLDS, r.verdict());
            } else {
                assertEquals(Verdict.VIOLATED, r.verdict());
                assertEquals(1000, r.firstViolation().timeMs());
                assertEquals(1501, r.firstViolation().detectedMs()); // known once b came, late
                assertEquals(Map.of("a", true, "b", false), r.firstViolation().values());
            }
        }
    }

    @Test
    public void aDeadlineExactlyAtTheEndIsDecidedOnePastItIsOpen() {
        for (long end : new long[] {1500, 1499}) {
            RequirementMonitors m = Traces.monitors(always(implies(is("a"), eventually(500, is("b")))));
            m.context(0, "a", false);
            m.context(0, "b", false);
            m.context(1000, "a", true);
            m.context(1001, "a", false);
            RequirementResult r = m.finish(end).get(0);
            if (end == 1500) { // the window [1000, 1500] lies inside the run: no b, a violation
                assertEquals(Verdict.VIOLATED, r.verdict());
                assertEquals(1000, r.firstViolation().timeMs());
            } else { // it reaches past the end: open, not a violation (weak end semantics)
                assertEquals(Verdict.OPEN, r.verdict());
                assertEquals(1000, r.openSinceMs());
            }
        }
    }

    /**
     * A bound past any run (within 99999999999999999999 hours is Long.MAX_VALUE ms in the generated
     * file) is a window the run never closes: open at the end, or violated inside it, never an overflow.
     */
    @Test
    public void aBoundPastAnyRunIsAWindowThatNeverClosesNotAnOverflow() {
        RequirementMonitors m = Traces.monitors(always(implies(is("a"), eventually(Long.MAX_VALUE, is("b")))),
                eventually(Long.MAX_VALUE, is("b")), temporal("always", Long.MAX_VALUE, x("<", 5)));
        m.context(0, "a", false);
        m.context(0, "b", false);
        m.context(0, "x", 1.0);
        m.context(1000, "a", true);
        m.context(2000, "x", 7.0);
        m.context(2500, "b", true); // met: a's obligation closes, b's window never does
        m.context(3000, "a", false);
        m.context(3000, "b", false);
        m.context(4000, "a", true);
        List<RequirementResult> r = m.finish(5000);
        assertEquals(List.of("open", "holds", "violated"), Traces.verdicts(r));
        assertEquals(4000, r.get(0).openSinceMs());
        assertEquals(2000, r.get(2).firstViolation().timeMs());
    }

    @Test
    public void simultaneousChangesAreTakenTogetherWhateverTheirOrder() {
        // at 1000 both x and the mode change: x > 5 implies fast never sees x high while slow
        RequirementMonitors m = Traces.monitors(always(implies(x(">", 5), modeIs(1))), always(implies(x(">", 5), modeIs(1))));
        m.context(0, "x", 1.0);
        m.context(1000, "x", 7.0);
        m.varpoint(1000, "mode", TextNode.valueOf("fast"));
        m.varpoint(2000, "mode", TextNode.valueOf("slow")); // the mode goes first here
        m.context(2000, "x", 2.0);
        m.context(3000, "x", 8.0); // but here x rises 1 ms before the mode follows
        m.varpoint(3001, "mode", TextNode.valueOf("fast"));
        RequirementResult r = m.finish(4000).get(0);
        assertEquals(1, r.violations());
        assertEquals(3000, r.firstViolation().timeMs());
        assertEquals(Map.of("x", 8.0, "mode", "slow"), r.firstViolation().values());
    }

    @Test
    public void nestedBoundsSlideTheirWindowsWithinEachOther() {
        // whenever a, within 2 s b must start to hold for 500 ms
        var f = always(implies(is("a"), eventually(2000, temporal("always", 500L, is("b")))));
        // b holds [1800, 2300]: from 1800 for 500 ms (both ends included), within 2 s of a at 0: holds
        assertEquals(Verdict.HOLDS, runNested(f, 1800, 2301).verdict());
        // b holds [1800, 2299]: 1 ms short, and any later start is too late for a at 0
        RequirementResult r = runNested(f, 1800, 2300);
        assertEquals(Verdict.VIOLATED, r.verdict());
        assertEquals(0, r.firstViolation().timeMs());
        assertEquals(2400, r.firstViolation().detectedMs()); // known once time had moved past 2299
        // b from 2000, the last start in time, to 2500: holds
        assertEquals(Verdict.HOLDS, runNested(f, 2000, 2501).verdict());
    }

    private static RequirementResult runNested(com.fasterxml.jackson.databind.JsonNode f, long bFrom, long bUntil) {
        RequirementMonitors m = Traces.monitors(f);
        m.context(0, "a", true);
        m.context(0, "b", false);
        m.context(1, "a", false);
        m.context(bFrom, "b", true);
        m.context(bUntil, "b", false);
        m.advance(2400);
        return m.finish(6000).get(0);
    }

    @Test
    public void anEventHoldsOnlyAtItsInstant() {
        RequirementMonitors m = Traces.monitors(always(implies(is("e"), x(">", 5))), eventually(1000, is("e")));
        m.context(0, "x", 1.0);
        m.context(300, "x", 7.0);
        m.context(500, "e", "");     // x is 7 then: fine
        m.context(800, "x", 1.0);    // a low x without an event: fine too
        m.context(900, "e", "");     // an event while x is low: a violation at 900
        List<RequirementResult> r = m.finish(2000);
        assertEquals(900, r.get(0).firstViolation().timeMs());
        assertEquals(1, r.get(0).violations());
        assertEquals(Verdict.HOLDS, r.get(1).verdict()); // eventually within 1 s from 0: the event at 500
    }

    @Test
    public void aFormulaOtherThanAlwaysIsDecidedAtInstantZeroWhenItsWindowCloses() {
        RequirementMonitors m = Traces.monitors(eventually(1000, is("a")), eventually(1000, is("b")));
        m.context(0, "a", false);
        m.context(0, "b", false);
        m.context(700, "a", true);
        m.context(1200, "b", true);
        List<RequirementResult> r = m.finish(3000);
        assertEquals(List.of("holds", "violated"), Traces.verdicts(r));
        assertEquals(1200, r.get(1).firstViolation().detectedMs()); // the first instant past the window
    }

    @Test
    public void aSignalThatNeverArrivesIsNeverEvaluatedNotAnError() {
        RequirementMonitors m = Traces.monitors(always(implies(is("a"), x("<", 5))), always(x("<", 5)));
        m.context(0, "a", false);
        List<RequirementResult> r = m.finish(10_000);
        assertEquals(List.of("not-evaluated", "not-evaluated"), Traces.verdicts(r));
        assertEquals(List.of("x"), r.get(1).neverValued());
        assertNull(r.get(1).firstViolation());
    }

    @Test
    public void badValuesAreCountedAndLeaveTheSignalAsItWas() {
        RequirementMonitors m = Traces.monitors(always(x("<", 5)));
        m.context(0, "x", 1.0);
        assertTrue(!m.context(10, "x", "high"));
        assertTrue(!m.varpoint(10, "mode", TextNode.valueOf("warp")));
        assertEquals(2, m.rejected());
        assertEquals(Verdict.HOLDS, m.finish(100).get(0).verdict());
    }

    @Test
    public void memoryIsBoundedByTheLargestWindowNotByTheRunsLength() {
        // an 8-hour run with a change every 100 ms and a 5-second window
        RequirementMonitors m = Traces.monitors(always(implies(is("a"), eventually(5000, is("b")))),
                always(op("or", x("<", 5), is("b"))));
        int most = 0;
        for (long t = 0; t < 8 * 3600_000L; t += 100) {
            m.context(t, "a", (t / 100) % 7 == 0);
            m.context(t, "b", (t / 100) % 5 == 0);
            m.context(t, "x", (double) ((t / 100) % 11));
            most = Math.max(most, m.remembered());
        }
        RequirementResult r = m.finish(8 * 3600_000L).get(0);
        assertEquals(Verdict.HOLDS, r.verdict());
        assertTrue("remembered " + most + " instants", most <= 5000 / 100 + 2);
    }
}
