package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.miron.runtime.roqme.Harness.bin;
import static org.miron.runtime.roqme.Harness.call;
import static org.miron.runtime.roqme.Harness.num;
import static org.miron.runtime.roqme.Harness.ref;
import static org.miron.runtime.roqme.Harness.time;

import java.util.List;
import java.util.Map;
import org.junit.Test;

/** Windows, trends, period, arithmetic, functions, arrays, derived contexts, params and vars. */
public class FunctionsTest {
    private static final List<String> O = List.of("o");
    private static final List<String> NONE = List.of();

    @Test
    public void timeWindowAverageSlidesAndDropsOldSamples() throws Exception {
        // avg(x, 30 seconds) as a var, to read it
        Harness h = new Harness().var("a", call("avg", ref("x"), time(30_000))).start();
        assertEquals(null, h.value("a")); // empty window: no average
        h.in("x", 10, 1_000);
        h.in("x", 20, 11_000);
        h.in("x", 60, 21_000);
        assertEquals(30.0, h.value("a"));
        h.until(31_000); // the sample of t=1000 leaves the window at 31000
        assertEquals(40.0, h.value("a"));
        h.until(51_000);
        assertEquals(null, h.value("a"));
    }

    @Test
    public void aTimeWindowDroppingASampleReEvaluatesThePattern() throws Exception {
        // avg(x, 10 seconds) < 50: fires when the high sample leaves, with no new input
        Harness h = new Harness().obs("o", bin("<", call("avg", ref("x"), time(10_000)), num(50))).start();
        assertEquals(NONE, h.in("x", 100, 1_000));
        assertEquals(NONE, h.in("x", 10, 5_000)); // avg 55
        assertEquals(NONE, h.until(10_999));
        assertEquals(O, h.until(11_000)); // avg 10
    }

    @Test
    public void sampleWindowAggregates() throws Exception {
        Harness h = new Harness()
                .var("a", call("avg", ref("x"), num(3))).var("lo", call("min", ref("x"), num(3)))
                .var("hi", call("max", ref("x"), num(3))).var("s", call("sum", ref("x"), num(3)))
                .var("c", call("count", ref("x"), num(3))).start();
        assertEquals(0.0, h.value("c"));
        assertEquals(0.0, h.value("s"));
        for (int i = 1; i <= 5; i++) {
            h.in("x", i * 10, i * 100); // 10 20 30 40 50: the window holds 30 40 50
        }
        assertEquals(40.0, h.value("a"));
        assertEquals(30.0, h.value("lo"));
        assertEquals(50.0, h.value("hi"));
        assertEquals(120.0, h.value("s"));
        assertEquals(3.0, h.value("c"));
    }

    @Test
    public void countOfEventsInATimeWindow() throws Exception {
        // var recentDeliveries : number := count(DeliveryDone, 10 minutes)
        Harness h = new Harness().var("n", call("count", ref("e"), time(600_000))).start();
        assertEquals(0.0, h.value("n"));
        h.in("e", true, 1_000);
        h.in("e", true, 2_000);
        h.in("e", true, 300_000);
        assertEquals(3.0, h.value("n"));
        h.until(601_000);
        assertEquals(2.0, h.value("n"));
        h.until(900_000);
        assertEquals(0.0, h.value("n"));
    }

    @Test
    public void trends() throws Exception {
        Harness h = new Harness().var("inc", call("increasing", ref("x"), num(3)))
                .var("dec", call("decreasing", ref("x"), num(3))).var("st", call("stable", ref("x"), num(3))).start();
        h.in("x", 1, 100);
        assertEquals(null, h.value("inc")); // one sample: no trend yet
        h.in("x", 2, 200);
        assertEquals(null, h.value("inc")); // the last 3 samples rise: there must be 3
        h.in("x", 3, 300);
        assertEquals(List.of(true, false, false), List.of(h.value("inc"), h.value("dec"), h.value("st")));
        h.in("x", 3, 400);
        assertEquals(List.of(false, false, false), List.of(h.value("inc"), h.value("dec"), h.value("st")));
        h.in("x", 3, 500);
        assertEquals(List.of(false, false, true), List.of(h.value("inc"), h.value("dec"), h.value("st")));
        h.in("x", 2, 600);
        h.in("x", 1, 700);
        assertEquals(List.of(false, true, false), List.of(h.value("inc"), h.value("dec"), h.value("st")));
    }

    @Test
    public void chargingPatternOfTheExample() throws Exception {
        // Docked and BatteryLevel'increasing(5)
        Harness h = new Harness().obs("o", bin("and", ref("b"), call("increasing", ref("x"), num(5)))).start();
        h.in("b", true, 100);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < 7; i++) {
            b.append(h.in("x", 20 + i, 1000 + i * 1000).isEmpty() ? '.' : 'F');
        }
        assertEquals("....F..", b.toString()); // the trend became true at the 5th sample, once
    }

    @Test
    public void periodIsTheTimeBetweenTheLastTwoUpdates() throws Exception {
        Harness h = new Harness().var("per", call("period", ref("x"))).start();
        h.in("x", 1, 1_000);
        assertEquals(null, h.value("per"));
        h.in("x", 1, 1_250);
        assertEquals(250.0, h.value("per"));
        h.in("x", 5, 2_000);
        assertEquals(750.0, h.value("per"));
    }

    @Test
    public void arithmeticAndMathFunctions() throws Exception {
        Harness h = new Harness()
                .var("v1", bin("-", bin("+", ref("x"), bin("*", ref("y"), num(2))), bin("/", ref("x"), num(4))))
                .var("v2", call("pow", ref("x"), num(2))).var("v3", call("sqrt", ref("x")))
                .var("v4", call("abs", "{\"op\":\"neg\",\"arg\":" + ref("x") + "}")).var("v5", call("exp", num(0)))
                .var("v6", "{\"op\":\"?:\",\"cond\":" + ref("b") + ",\"then\":" + num(1) + ",\"else\":" + num(2) + "}")
                .start();
        assertEquals(null, h.value("v1")); // reads unknown contexts
        assertEquals(1.0, h.value("v5"));
        h.in("x", 16, 100);
        h.in("y", 3, 200);
        assertEquals(18.0, h.value("v1"));
        assertEquals(256.0, h.value("v2"));
        assertEquals(4.0, h.value("v3"));
        assertEquals(16.0, h.value("v4"));
        assertEquals(null, h.value("v6"));
        h.in("b", false, 300);
        assertEquals(2.0, h.value("v6"));
    }

    @Test
    public void arraysAndTheirFunctions() throws Exception {
        Harness h = new Harness().var("fi", call("first", ref("arr"))).var("la", call("last", ref("arr")))
                .var("a1", call("at", ref("arr"), num(1))).var("sz", call("size", ref("arr")))
                .var("av", call("avg", ref("arr"))).var("em", call("isEmpty", ref("arr"))).start();
        assertEquals(null, h.value("em"));
        h.in("arr", List.of(1.0, 2.0, 6.0), 100);
        assertEquals(List.of(1.0, 6.0, 2.0, 3.0, 3.0),
                List.of(h.value("fi"), h.value("la"), h.value("a1"), h.value("sz"), h.value("av")));
        assertEquals(false, h.value("em"));
        Harness g = new Harness().obs("o", call("includes", ref("arr"), num(5))).start();
        assertEquals(NONE, g.in("arr", List.of(1.0, 2.0, 3.0), 100));
        assertEquals(O, g.in("arr", List.of(1.0, 5.0, 3.0), 200));
    }

    @Test
    public void derivedContextsFollowTheirInputs() throws Exception {
        Harness h = new Harness().obs("o", bin(">", ref("d"), num(10))).start();
        assertEquals(null, h.value("d"));
        assertEquals(NONE, h.in("x", 4, 100));
        assertEquals(8.0, h.value("d"));
        assertEquals(O, h.in("x", 6, 200));
    }

    @Test
    public void paramsTakeTheirDefaultOrTheValueGivenAtStart() throws Exception {
        Harness h = new Harness().obs("o", bin("<", ref("x"), ref("P"))).start();
        assertEquals(O, h.in("x", 25, 100)); // default 30
        Harness g = new Harness().obs("o", bin("<", ref("x"), ref("P"))).start(Map.of("P", "20"), 1000);
        assertEquals(NONE, g.in("x", 25, 100));
        assertEquals(O, g.in("x", 15, 200));
    }

    @Test
    public void setsAssignsAVarThatOtherPatternsSee() throws Exception {
        Harness h = new Harness().var("count", num(0))
                .obs("inc", Harness.ref("e"), "{\"kind\":\"sets\",\"var\":\"count\",\"value\":" + bin("+", ref("count"), num(1)) + "}")
                .obs("o", bin(">=", ref("count"), num(2))).start();
        assertEquals(0.0, h.value("count"));
        assertEquals(List.of("inc"), h.in("e", true, 100));
        assertEquals(List.of("inc", "o"), h.in("e", true, 200));
        assertEquals(2.0, h.value("count"));
    }
}
