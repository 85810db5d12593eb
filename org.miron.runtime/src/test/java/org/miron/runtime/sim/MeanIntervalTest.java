package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.Test;

/** The mean's 95 % interval over runs (Statistics.of): a bootstrap percentile interval. */
public class MeanIntervalTest {
    /** The case: near misses over 3 runs had the t interval [-6.6, 29.3]; a count stays at or above 0. */
    @Test
    public void aCountOrAShareNeverLeavesItsRange() {
        Statistics.Summary misses = Statistics.of(List.of(0.0, 3.0, 31.0));
        assertTrue(misses.toString(), misses.lo() >= 0 && misses.hi() <= 31);
        assertTrue(misses.toString(), misses.lo() < misses.mean() && misses.mean() < misses.hi());
        Statistics.Summary share = Statistics.of(List.of(0.0, 0.0, 0.138, 0.0));
        assertTrue(share.toString(), share.lo() >= 0 && share.hi() <= 1);
        Statistics.Summary metric = Statistics.of(List.of(0.99, 1.0, 0.97));
        assertTrue(metric.toString(), metric.hi() <= 1);
    }

    /** Many runs of a normal measure: the bootstrap interval is the textbook t interval, within 5 %. */
    @Test
    public void withManyRunsItIsTheStudentInterval() {
        Random r = new Random(3);
        List<Double> x = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            x.add(10 + 2 * r.nextGaussian());
        }
        double mean = x.stream().mapToDouble(Double::doubleValue).average().orElseThrow();
        double ss = x.stream().mapToDouble(v -> (v - mean) * (v - mean)).sum();
        double half = 1.972 * Math.sqrt(ss / 199) / Math.sqrt(200); // t(0.975, 199)
        Statistics.Summary s = Statistics.of(x);
        assertEquals(mean, s.mean(), 1e-12);
        assertEquals(half, (s.hi() - s.lo()) / 2, 0.05 * half);
        assertEquals("about symmetric", mean, (s.hi() + s.lo()) / 2, 0.1 * half);
    }

    @Test
    public void oneRunOrEqualRunsAreTheirValueAndTheSameRunsTheSameInterval() {
        assertEquals(new Statistics.Summary(4, 4, 4), Statistics.of(List.of(4.0)));
        assertEquals(new Statistics.Summary(0, 0, 0), Statistics.of(List.of(0.0, 0.0, 0.0)));
        assertEquals(Statistics.of(List.of(1.0, 5.0, 2.0, 8.0)), Statistics.of(List.of(1.0, 5.0, 2.0, 8.0)));
    }
}
