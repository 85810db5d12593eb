package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.miron.runtime.roqme.Harness.bin;
import static org.miron.runtime.roqme.Harness.ref;

import java.util.List;
import org.junit.Test;
import org.miron.runtime.roqme.reasoner.Reasoner;
import org.miron.runtime.roqme.reasoner.Strength;

/** The reasoner's rules one by one (shared/spec/roqme-runtime.md, "The reasoner"). */
public class ReasonerTest {
    private static final double EPS = 1e-12;

    private static String act(String kind, String belief, String strength, Long survival) {
        return "{\"kind\":\"" + kind + "\",\"belief\":\"" + belief + "\",\"strength\":" + (strength == null ? "null" : "\"" + strength + "\"")
                + ",\"survivalMs\":" + survival + "}";
    }

    @Test
    public void ratioTable() {
        String[] s = {null, "MEDIUM", "VERYHIGH", "HIGH", "LOW", "VERYLOW"};
        double[] r = {0.5, 0.5, 0.1, 0.3, 0.7, 0.9};
        for (int i = 0; i < s.length; i++) {
            assertEquals(r[i], Strength.ratio("reinforces", s[i]), EPS);
            assertEquals(1 / r[i], Strength.ratio("undermines", s[i]), EPS);
        }
        assertEquals(10 / 3.0, Strength.ratio("undermines", "high"), EPS);
    }

    @Test
    public void noEvidenceIsTheReference() {
        Reasoner r = new Reasoner(1000, new double[] {0.5, 0.8, 0.0});
        assertEquals(0.5, r.estimate(0, 1), EPS);
        assertEquals(0.8, r.estimate(1, 1), EPS);
        assertEquals(0.0, r.estimate(2, 1), EPS);
    }

    @Test
    public void freshEvidenceHasItsRatio() {
        Reasoner r = new Reasoner(1000, new double[] {0.5});
        r.add(0, 0.3, 60_000, 1);
        // lr = 0.3, belief = 1/1.3, estimate with ref 0.5 = belief
        assertEquals(1 / 1.3, r.estimate(0, 1), EPS);
    }

    @Test
    public void estimateMapsAroundTheReference() {
        assertEquals(0.8, Reasoner.estimate(0.5, 0.8), EPS);
        assertEquals(2 * 0.25 * 0.8, Reasoner.estimate(0.25, 0.8), EPS);
        assertEquals(2 * 0.75 * 0.2 + 1.6 - 1, Reasoner.estimate(0.75, 0.8), EPS);
        assertEquals(1.0, Reasoner.estimate(1.0, 0.8), EPS);
        assertEquals(0.0, Reasoner.estimate(0.0, 0.8), EPS);
    }

    @Test
    public void ratioDecaysTo095AtItsSurvival() {
        for (double ratio : new double[] {0.1, 0.3, 0.5, 0.7, 0.9}) {
            Reasoner r = new Reasoner(1000, new double[] {0.5});
            r.add(0, ratio, 30_000, 0);
            double belief = r.estimate(0, 30); // ref 0.5: the estimate is the belief 1/(1+ratio)
            assertEquals("r=" + ratio, 0.95, 1 / belief - 1, 1e-9);
            Reasoner u = new Reasoner(1000, new double[] {0.5});
            u.add(0, 1 / ratio, 30_000, 0);
            assertEquals("1/r=" + ratio, 1 / 0.95, 1 / u.estimate(0, 30) - 1, 1e-9);
        }
    }

    @Test
    public void fadedEvidenceIsDroppedForGood() {
        Reasoner r = new Reasoner(1000, new double[] {0.5});
        r.add(0, 0.5, 10_000, 0);
        int k = 0;
        while (r.evidenceCount(0) > 0) {
            r.estimate(0, ++k);
        }
        // dropped at the first tick whose ratio is within 0.01 of 1: just after the 0.95 at 10 s
        Reasoner probe = new Reasoner(1000, new double[] {0.5});
        probe.add(0, 0.5, 10_000, 0);
        double before = 1 / probe.estimate(0, k - 1) - 1;
        assertEquals(true, Math.abs(before - 1) >= 0.01);
        assertEquals(0.5, r.estimate(0, k + 1000), EPS);
        assertEquals(true, k > 10 && k < 40);
    }

    @Test
    public void anObservationFiredTwiceInATickCountsOnce() throws Exception {
        Harness twice = new Harness().obs("o", ref("e"), act("undermines", "p", null, null)).start();
        twice.in("e", true, 100);
        twice.in("e", true, 200);
        Harness once = new Harness().obs("o", ref("e"), act("undermines", "p", null, null)).start();
        once.in("e", true, 100);
        assertEquals(once.provider.tick().estimates()[0], twice.provider.tick().estimates()[0], EPS);
        assertEquals(1 / 3.0, once.provider.estimate(0), EPS);
    }

    @Test
    public void survivalDefaultsToTheBeliefsThenFiveMinutes() throws Exception {
        String q = "{" + Harness.decl("q") + ",\"kind\":\"property\",\"reference\":0.5,\"survivalMs\":20000,\"expr\":null}";
        Harness h = new Harness().belief(q)
                .obs("o", ref("e"), act("reinforces", "p", null, null), act("reinforces", "q", null, null),
                        act("reinforces", "q", null, 60_000L)).start(java.util.Map.of(), 1000);
        h.in("e", true, 100);
        Provider.Tick t = null;
        for (int k = 1; k <= 21; k++) {
            t = h.provider.tick();
        }
        // at tick 21 the evidence is 20 s old
        double pExpected = ratioAt(0.5, 20_000, 300_000);
        double qExpected = ratioAt(0.5, 20_000, 20_000) * ratioAt(0.5, 20_000, 60_000);
        assertEquals(Reasoner.estimate(1 / (1 + pExpected), 0.5), t.estimates()[0], EPS);
        assertEquals(Reasoner.estimate(1 / (1 + qExpected), 0.5), t.estimates()[1], EPS);
    }

    private static double ratioAt(double r, double age, double survival) {
        double p1 = 1 / (1 + r);
        double p0 = r * p1;
        double lambda = (Math.log(Math.abs(p1 - 0.5)) - Math.log(1 / 78.0)) / (2 * survival);
        double f = Math.exp(-2 * lambda * age);
        return ((p0 - 0.5) * f + 0.5) / ((p1 - 0.5) * f + 0.5);
    }

    @Test
    public void clearsDropsAllEvidence() throws Exception {
        Harness h = new Harness().obs("o", ref("e"), act("undermines", "p", "VERYHIGH", null))
                .obs("c", ref("f"), "{\"kind\":\"clears\",\"belief\":\"p\"}").start();
        h.in("e", true, 100);
        assertEquals(2 * (1 / 11.0) * 0.5, h.provider.tick().estimates()[0], EPS);
        h.in("f", true, 1100);
        assertEquals(0.5, h.provider.tick().estimates()[0], EPS);
    }

    @Test
    public void evidenceIsAddedAtTheTickAndAgedByWholeTicks() throws Exception {
        Harness h = new Harness().obs("o", ref("e"), act("undermines", "p", null, 60_000L)).start();
        h.in("e", true, 999); // fired in tick 1: age 0 at tick 1
        assertEquals(List.of("o"), h.provider.tick().fired());
        assertEquals(1 / 3.0, h.provider.estimate(0), EPS);
        Provider.Tick t2 = h.provider.tick();
        assertEquals(List.of(), t2.fired());
        assertEquals(1 / (1 + ratioAt(2, 1000, 60_000)), t2.estimates()[0], EPS);
    }

    @Test
    public void propertyDefinedByAnExpression() throws Exception {
        String q = "{" + Harness.decl("q") + ",\"kind\":\"beliefvar\",\"reference\":0.8,\"survivalMs\":null,\"expr\":null}";
        String avg = "{" + Harness.decl("both") + ",\"kind\":\"property\",\"reference\":0.5,\"survivalMs\":null,\"expr\":"
                + bin("/", bin("+", "{\"belief\":\"p\"}", ref("q")), Harness.num(2)) + "}";
        Harness h = new Harness().belief(q).belief(avg).obs("o", ref("e"), act("undermines", "p", null, null)).start();
        Provider.Tick t = h.provider.tick();
        assertEquals(2, t.estimates().length); // p and both; q is a beliefvar, not published
        assertEquals(0.65, t.estimates()[1], EPS);
        h.in("e", true, 1500);
        t = h.provider.tick();
        assertEquals((1 / 3.0 + 0.8) / 2, t.estimates()[1], EPS);
    }

    @Test
    public void patternsCanReadEstimates() throws Exception {
        Harness h = new Harness().obs("o", ref("e"), act("undermines", "p", "VERYHIGH", null))
                .obs("alarm", bin("<", ref("p"), Harness.num(0.2)), "{\"kind\":\"clears\",\"belief\":\"p\"}").start();
        h.in("e", true, 100);
        assertEquals(List.of("o"), h.provider.tick().fired()); // p = 0.0909: alarm fires after the tick
        assertEquals(List.of("alarm"), h.provider.tick().fired());
        assertEquals(0.5, h.provider.estimate(0), EPS);
    }
}
