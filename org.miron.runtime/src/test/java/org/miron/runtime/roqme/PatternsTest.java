package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.miron.runtime.roqme.Harness.bin;
import static org.miron.runtime.roqme.Harness.call;
import static org.miron.runtime.roqme.Harness.num;
import static org.miron.runtime.roqme.Harness.ref;
import static org.miron.runtime.roqme.Harness.un;

import java.util.List;
import org.junit.Test;

/** The pattern operators, each on the examples of the RoQME syntax guide (shared/spec/roqme-runtime.md). */
public class PatternsTest {
    private static final List<String> O = List.of("o");
    private static final List<String> NONE = List.of();

    @Test
    public void booleanPatternIsEventWhen() throws Exception {
        Harness h = new Harness().obs("o", bin(">", ref("x"), num(45))).start();
        assertEquals(NONE, h.in("x", 40, 100));
        assertEquals(O, h.in("x", 50, 200)); // becomes true
        assertEquals(NONE, h.in("x", 60, 300)); // stays true: no new event
        assertEquals(NONE, h.in("x", 30, 400));
        assertEquals(O, h.in("x", 46, 500));
    }

    @Test
    public void firstKnownTrueValueIsAnEvent() throws Exception {
        Harness h = new Harness().obs("o", bin(">", ref("x"), num(45))).start();
        assertEquals(O, h.in("x", 50, 100));
    }

    @Test
    public void updateOfAPlainVariableIsEverySample() throws Exception {
        Harness h = new Harness().obs("o", ref("x")).start(); // a number as a pattern: update(x)
        assertEquals(O, h.in("x", 1, 100));
        assertEquals(O, h.in("x", 1, 200)); // even an equal one
        Harness g = new Harness().obs("o", call("update", ref("x"))).start();
        assertEquals(O, g.in("x", 7, 100));
        assertEquals(O, g.in("x", 7, 200));
        assertEquals(NONE, g.in("y", 7, 300));
    }

    @Test
    public void updateOfACompoundExpressionIsAChange() throws Exception {
        Harness h = new Harness().obs("o", call("update", bin(">", ref("x"), num(45)))).start();
        assertEquals(O, h.in("x", 50, 100)); // unknown -> true
        assertEquals(NONE, h.in("x", 60, 200));
        assertEquals(O, h.in("x", 10, 300)); // true -> false
        assertEquals(NONE, h.in("x", 20, 400));
        assertEquals(O, h.in("x", 46, 500)); // false -> true
    }

    @Test
    public void eventWhenCall() throws Exception {
        Harness h = new Harness().obs("o", call("eventWhen", bin("<", ref("x"), ref("y")))).start();
        assertEquals(NONE, h.in("x", 1, 100)); // y unknown
        assertEquals(O, h.in("y", 2, 200));
        assertEquals(NONE, h.in("y", 3, 300));
        assertEquals(NONE, h.in("x", 5, 400));
        assertEquals(O, h.in("y", 6, 500));
    }

    @Test
    public void booleanContextAsPatternFiresWhenItBecomesTrue() throws Exception {
        Harness h = new Harness().obs("o", ref("b")).start();
        assertEquals(O, h.in("b", true, 100));
        assertEquals(NONE, h.in("b", true, 200));
        assertEquals(NONE, h.in("b", false, 300));
        assertEquals(O, h.in("b", true, 400));
    }

    @Test
    public void valueLogicFiresWhenTheWholeExpressionBecomesTrue() throws Exception {
        // ctx1 > 25 & ctx2
        Harness h = new Harness().obs("o", bin("&", bin(">", ref("x"), num(25)), ref("b"))).start();
        assertEquals(NONE, h.in("x", 30, 100)); // b unknown
        assertEquals(NONE, h.in("b", false, 200));
        assertEquals(O, h.in("b", true, 300));
        assertEquals(NONE, h.in("x", 40, 400));
        assertEquals(NONE, h.in("x", 20, 500));
        assertEquals(O, h.in("x", 26, 600));
    }

    @Test
    public void eventLogicAndFiresOnceBothOccurredInAnyOrder() throws Exception {
        // ctx1 > 25 and ctx2
        Harness h = new Harness().obs("o", bin("and", bin(">", ref("x"), num(25)), ref("b"))).start();
        assertEquals(NONE, h.in("b", true, 100)); // b's event
        assertEquals(NONE, h.in("b", false, 150));
        assertEquals(O, h.in("x", 30, 200)); // x > 25's event: both have occurred, b is false now
        assertEquals(NONE, h.in("x", 10, 300));
        assertEquals(NONE, h.in("x", 30, 400)); // a new x event alone
        assertEquals(O, h.in("b", true, 500));
    }

    @Test
    public void eventLogicOrFiresOnEither() throws Exception {
        Harness h = new Harness().obs("o", bin("or", ref("e"), ref("f"))).start();
        assertEquals(O, h.in("e", true, 100));
        assertEquals(O, h.in("f", true, 200));
        assertEquals(NONE, h.in("x", 1, 300));
    }

    @Test
    public void andNotFiresOnAWithoutB() throws Exception {
        Harness h = new Harness().obs("o", bin("and", ref("e"), un("not", ref("f")))).start();
        assertEquals(O, h.in("e", true, 100));
        assertEquals(NONE, h.in("f", true, 200));
        assertEquals(NONE, h.in("e", true, 300)); // f occurred since the last e
        assertEquals(O, h.in("e", true, 400)); // restarted after the previous e
    }

    @Test
    public void followedByMatchesEachAWithTheFirstBAfterIt() throws Exception {
        Harness h = new Harness().obs("o", bin("->", ref("e"), ref("f"))).start();
        assertEquals(NONE, h.in("f", true, 100)); // no A yet
        assertEquals(NONE, h.in("e", true, 200));
        assertEquals(O, h.in("f", true, 300));
        assertEquals(NONE, h.in("f", true, 400)); // a second B needs a new A
        assertEquals(NONE, h.in("e", true, 500));
        assertEquals(NONE, h.in("e", true, 600));
        assertEquals(O, h.in("f", true, 700));
        assertEquals(NONE, h.in("f", true, 800));
    }

    @Test
    public void followedByAppliesEventWhenToEachSide() throws Exception {
        Harness h = new Harness().obs("o", bin("->", bin(">", ref("x"), num(10)), bin(">", ref("y"), num(10)))).start();
        assertEquals(NONE, h.in("y", 20, 100));
        assertEquals(NONE, h.in("x", 20, 200));
        assertEquals(NONE, h.in("y", 30, 300)); // y > 10 stays true: no event
        assertEquals(NONE, h.in("y", 0, 400));
        assertEquals(O, h.in("y", 11, 500));
    }

    @Test
    public void repeatFiresEveryNthOccurrence() throws Exception {
        Harness h = new Harness().obs("o", "{\"op\":\"repeat\",\"arg\":" + ref("e") + ",\"times\":3}").start();
        StringBuilder b = new StringBuilder();
        for (int i = 1; i <= 7; i++) {
            b.append(h.in("e", true, i * 100).isEmpty() ? '.' : 'F');
        }
        assertEquals("..F..F.", b.toString());
    }

    @Test
    public void rangeFiresOnTheATHToBthOccurrenceAndStartsAgain() throws Exception {
        Harness h = new Harness().obs("o", "{\"op\":\"range\",\"arg\":" + ref("e") + ",\"min\":2,\"max\":3}").start();
        StringBuilder b = new StringBuilder();
        for (int i = 1; i <= 7; i++) {
            b.append(h.in("e", true, i * 100).isEmpty() ? '.' : 'F');
        }
        assertEquals(".FF.FF.", b.toString());
    }

    @Test
    public void onceFiresOnlyTheFirstTimeEver() throws Exception {
        Harness h = new Harness().obs("o", un("once", ref("e"))).start();
        assertEquals(O, h.in("e", true, 100));
        assertEquals(NONE, h.in("e", true, 200));
        assertEquals(NONE, h.in("e", true, 300));
    }

    @Test
    public void withoutOnceAPatternIsDetectedAgainAndAgain() throws Exception {
        Harness h = new Harness().obs("o", ref("e")).start();
        for (int i = 1; i <= 5; i++) {
            assertEquals(O, h.in("e", true, i * 100));
        }
    }

    @Test
    public void whileFiresWhenTheConditionHoldsAtThatInstant() throws Exception {
        Harness h = new Harness().obs("o", "{\"op\":\"while\",\"arg\":" + ref("e") + ",\"cond\":"
                + bin("=", ref("mode"), Harness.enumLit("HIGH")) + "}").start();
        assertEquals(NONE, h.in("e", true, 100)); // mode unknown
        assertEquals(NONE, h.in("mode", "HIGH", 200)); // the condition alone is no event
        assertEquals(O, h.in("e", true, 300));
        assertEquals(NONE, h.in("mode", "LOW", 400));
        assertEquals(NONE, h.in("e", true, 500));
    }

    @Test
    public void unknownNeverFires() throws Exception {
        Harness h = new Harness().obs("o", bin("|", bin(">", ref("x"), num(1)), ref("b"))).start();
        assertEquals(NONE, h.in("b", true, 100)); // x unknown: x > 1 | b is unknown (strict propagation)
        assertEquals(O, h.in("x", 0, 200));
        assertEquals(null, new Harness().start().value("x"));
    }
}
