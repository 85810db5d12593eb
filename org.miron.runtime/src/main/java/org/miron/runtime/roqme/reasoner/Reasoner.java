package org.miron.runtime.roqme.reasoner;

import java.util.ArrayList;
import java.util.List;

/**
 * The reasoner the MIRoN demonstrators ran (docs/roqme-provider.md, "Reasoner"): per belief, pieces of
 * evidence whose likelihood ratio decays from r towards 1 with their age in whole ticks; a piece
 * with |ratio - 1| < 0.01 is dropped for good. The belief is 1/(1 + product of ratios) and the
 * estimate maps it around the belief's reference.
 */
public final class Reasoner {
    /** One piece of evidence: ratio r added at a tick, decaying with rate λ (per ms). */
    record Evidence(double p0, double p1, double lambda, long tick) {
        double ratio(double ageMs) {
            double f = Math.exp(-2 * lambda * ageMs);
            double a = (p0 - 0.5) * f + 0.5;
            double b = (p1 - 0.5) * f + 0.5;
            return a / b;
        }
    }

    private static final double LN_1_78 = Math.log(1.0 / 78);
    private final long periodMs;
    private final double[] refs;
    private final List<List<Evidence>> evidence = new ArrayList<>();

    /** @param refs each belief's reference, in the order of the belief indexes used below */
    public Reasoner(long periodMs, double[] refs) {
        this.periodMs = periodMs;
        this.refs = refs.clone();
        for (int i = 0; i < refs.length; i++) {
            evidence.add(new ArrayList<>());
        }
    }

    /** Adds a piece of evidence of ratio r to belief b at tick k. */
    public void add(int b, double r, long survivalMs, long k) {
        double p1 = 1 / (1 + r);
        double p0 = r * p1;
        double lambda = (Math.log(Math.abs(p1 - 0.5)) - LN_1_78) / (2.0 * survivalMs);
        evidence.get(b).add(new Evidence(p0, p1, lambda, k));
    }

    /** {@code clears}: drops all evidence of belief b. */
    public void clear(int b) {
        evidence.get(b).clear();
    }

    /** Number of live pieces of evidence of belief b (after the last {@link #estimate}). */
    public int evidenceCount(int b) {
        return evidence.get(b).size();
    }

    /** The estimate of belief b at tick k, dropping the evidence that has faded out. */
    public double estimate(int b, long k) {
        double lr = 1;
        List<Evidence> list = evidence.get(b);
        for (int i = 0; i < list.size(); i++) {
            Evidence e = list.get(i);
            double ratio = e.ratio((double) (k - e.tick()) * periodMs);
            if (Math.abs(ratio - 1) < 0.01) {
                list.remove(i--);
                continue;
            }
            lr *= ratio;
        }
        return estimate(1 / (1 + lr), refs[b]);
    }

    /** The estimate of a belief probability around a reference: ref with no evidence. */
    public static double estimate(double belief, double ref) {
        return belief < 0.5 ? 2 * belief * ref : 2 * belief * (1 - ref) + 2 * ref - 1;
    }
}
