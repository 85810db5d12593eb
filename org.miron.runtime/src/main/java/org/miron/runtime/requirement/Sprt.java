package org.miron.runtime.requirement;

/**
 * Wald's sequential probability ratio test for a probabilistic requirement {@code φ with probability
 * >= p}: each run satisfies φ or not, with an unknown probability θ. It tests H0: θ ≥ p + δ (the
 * requirement holds) against H1: θ ≤ p − δ (it fails), where δ is the half-width of the
 * indifference region (narrowed so that both ends stay inside (0, 1)); α bounds the probability of
 * answering "fails" when H0 is true, β that of answering "holds" when H1 is true. After each run
 * the log likelihood ratio {@code Σ log(P1(x)/P0(x))} is compared with Wald's bounds
 * {@code log((1−β)/α)} (then: fails) and {@code log(β/(1−α))} (then: holds); in between it asks for
 * another run. Between p − δ and p + δ either answer may come.
 */
public final class Sprt {
    public enum Decision { HOLDS, FAILS, UNDECIDED }

    private final double p0;
    private final double p1;
    private final double accept;
    private final double reject;
    private double llr;
    private int runs;
    private int satisfied;
    private Decision decision = Decision.UNDECIDED;
    private int decidedAt;

    public Sprt(double p, double delta, double alpha, double beta) {
        if (!(p > 0 && p < 1) || !(delta > 0) || !(alpha > 0 && alpha < 0.5) || !(beta > 0 && beta < 0.5)) {
            throw new IllegalArgumentException("SPRT needs 0 < p < 1, δ > 0 and 0 < α, β < 0.5");
        }
        double d = Math.min(delta, Math.min(p, 1 - p) / 2);
        this.p0 = p + d;
        this.p1 = p - d;
        this.reject = Math.log((1 - beta) / alpha);
        this.accept = Math.log(beta / (1 - alpha));
    }

    /** Takes one more run's outcome; once decided, further runs change nothing. */
    public Decision add(boolean satisfiedRun) {
        if (decision != Decision.UNDECIDED) {
            return decision;
        }
        runs++;
        if (satisfiedRun) {
            satisfied++;
            llr += Math.log(p1 / p0);
        } else {
            llr += Math.log((1 - p1) / (1 - p0));
        }
        if (llr >= reject) {
            decision = Decision.FAILS;
        } else if (llr <= accept) {
            decision = Decision.HOLDS;
        }
        if (decision != Decision.UNDECIDED) {
            decidedAt = runs;
        }
        return decision;
    }

    public Decision decision() {
        return decision;
    }

    /** Runs taken into account: the run that decided, or all so far. */
    public int runs() {
        return runs;
    }

    public int satisfied() {
        return satisfied;
    }

    public int decidedAt() {
        return decidedAt;
    }

    /** The indifference region's ends, {@code [p − δ, p + δ]}. */
    public double lower() {
        return p1;
    }

    public double upper() {
        return p0;
    }
}
