package org.miron.runtime.requirement;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.Random;
import org.junit.Test;

/** Clopper–Pearson against published values; Wald's SPRT's error rates on Bernoulli processes of known p. */
public class StatisticsTest {
    @Test
    public void clopperPearsonMatchesTheTextbookValues() {
        // 0 of 10: [0, 1 - 0.025^(1/10)] = [0, 0.3085]; 10 of 10: [0.025^(1/10), 1] (closed forms)
        ClopperPearson.Interval none = ClopperPearson.of(0, 10, 0.95);
        assertEquals(0, none.lo(), 0);
        assertEquals(1 - Math.pow(0.025, 0.1), none.hi(), 1e-9);
        ClopperPearson.Interval all = ClopperPearson.of(10, 10, 0.95);
        assertEquals(Math.pow(0.025, 0.1), all.lo(), 1e-9);
        assertEquals(1, all.hi(), 0);
        // 5 of 10 at 95 %: [0.1871, 0.8129] (Clopper & Pearson's tables, as R's binom.test gives them)
        ClopperPearson.Interval half = ClopperPearson.of(5, 10, 0.95);
        assertEquals(0.187086, half.lo(), 1e-5);
        assertEquals(0.812914, half.hi(), 1e-5);
        assertEquals(0.5, half.estimate(), 0);
    }

    @Test
    public void clopperPearsonCoversTheTrueProportionAtLeastAsOftenAsItSays() {
        Random rnd = new Random(7);
        double p = 0.13;
        int n = 40;
        int covered = 0;
        int trials = 4000;
        for (int i = 0; i < trials; i++) {
            int x = 0;
            for (int k = 0; k < n; k++) {
                x += rnd.nextDouble() < p ? 1 : 0;
            }
            ClopperPearson.Interval ci = ClopperPearson.of(x, n, 0.95);
            covered += ci.lo() <= p && p <= ci.hi() ? 1 : 0;
        }
        assertTrue("coverage " + covered / (double) trials, covered / (double) trials >= 0.94); // exact: >= 95 % up to sampling
    }

    @Test
    public void sprtErrorRatesStayWithinTheirBoundsOnAProcessOfKnownProbability() {
        double alpha = 0.05;
        double beta = 0.05;
        Random rnd = new Random(35);
        int tests = 2000;
        // true probability of satisfying at the edges of the indifference region of p = 0.9 ± 0.05
        int wrongFails = errors(rnd, 0.95, Sprt.Decision.FAILS, tests, alpha, beta);
        int wrongHolds = errors(rnd, 0.85, Sprt.Decision.HOLDS, tests, alpha, beta);
        // Wald's bounds: α/(1-β) and β/(1-α), here 0.0526; three standard errors of sampling on top
        double bound = alpha / (1 - beta) + 3 * Math.sqrt(0.0526 * 0.9474 / tests);
        assertTrue("false 'fails' rate " + wrongFails / (double) tests, wrongFails / (double) tests <= bound);
        assertTrue("false 'holds' rate " + wrongHolds / (double) tests, wrongHolds / (double) tests <= bound);
        // far from the threshold the test is right almost always, and quickly
        Sprt clear = new Sprt(0.9, 0.05, alpha, beta);
        int runs = 0;
        while (clear.decision() == Sprt.Decision.UNDECIDED) {
            clear.add(rnd.nextDouble() < 0.5);
            runs++;
        }
        assertEquals(Sprt.Decision.FAILS, clear.decision());
        assertTrue("decided after " + runs, runs < 15);
    }

    private static int errors(Random rnd, double theta, Sprt.Decision wrong, int tests, double alpha, double beta) {
        int errors = 0;
        for (int i = 0; i < tests; i++) {
            Sprt t = new Sprt(0.9, 0.05, alpha, beta);
            for (int k = 0; k < 100_000 && t.decision() == Sprt.Decision.UNDECIDED; k++) {
                t.add(rnd.nextDouble() < theta);
            }
            errors += t.decision() == wrong ? 1 : 0;
        }
        return errors;
    }

    @Test
    public void sprtAllRunsSatisfiedHoldsAfterWaldsNumberOfRuns() {
        Sprt t = new Sprt(0.9, 0.05, 0.05, 0.05);
        int runs = 0;
        while (t.add(true) == Sprt.Decision.UNDECIDED) {
            runs++;
        }
        // log(0.05/0.95) / log(0.85/0.95) = 26.5: the 27th satisfied run decides
        assertEquals(27, t.decidedAt());
        assertEquals(26, runs);
    }
}
