package org.miron.runtime.roqme.reasoner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The reasoner the MIRoN demonstrators ran (docs/roqme-provider.md, "Reasoner"): per belief, pieces of
 * evidence whose likelihood ratio decays from r towards 1 with their age in whole ticks; a piece
 * with |ratio - 1| < 0.01 is dropped for good. The belief is 1/(1 + product of ratios) and the
 * estimate maps it around the belief's reference.
 *
 * <p>Why a table: a piece's ratio depends only on (r, survival) and its age in ticks, and the decay
 * is monotonic, so the ratios of each (r, survival) are computed once per age (same formula, same
 * doubles) and a piece is dropped once its age reaches the first age within 0.01 of 1. A tick then
 * costs one multiplication per live piece instead of an exp.
 */
public final class Reasoner {
    private static final double LN_1_78 = Math.log(1.0 / 78);

    /** Evidence of one ratio and survival: its ratio by age in ticks. */
    static final class Kind {
        final double r;
        final long survivalMs;
        final double p0;
        final double p1;
        final double lambda;
        final long periodMs;
        double[] table = new double[64];
        int computed;
        int dropAge = Integer.MAX_VALUE; // first age whose ratio is within 0.01 of 1

        Kind(double r, long survivalMs, long periodMs) {
            this.r = r;
            this.survivalMs = survivalMs;
            p1 = 1 / (1 + r);
            p0 = r * p1;
            lambda = (Math.log(Math.abs(p1 - 0.5)) - LN_1_78) / (2.0 * survivalMs);
            this.periodMs = periodMs;
        }

        double ratio(double ageMs) {
            double f = Math.exp(-2 * lambda * ageMs);
            double a = (p0 - 0.5) * f + 0.5;
            double b = (p1 - 0.5) * f + 0.5;
            return a / b;
        }

        /** The ratio at an age in ticks, or NaN once the piece is to be dropped. */
        double at(long age) {
            if (age >= dropAge) {
                return Double.NaN;
            }
            while (computed <= age && computed < dropAge) {
                if (computed == table.length) {
                    table = Arrays.copyOf(table, table.length * 2);
                }
                double r = ratio((double) computed * periodMs);
                if (Math.abs(r - 1) < 0.01) {
                    dropAge = computed;
                    break;
                }
                table[computed++] = r;
            }
            return age >= dropAge ? Double.NaN : table[(int) age];
        }
    }

    /** Live pieces of one belief: their kind and the tick they were added at. */
    private static final class Pieces {
        Kind[] kinds = new Kind[8];
        long[] ticks = new long[8];
        int size;

        void add(Kind k, long tick) {
            if (size == kinds.length) {
                kinds = Arrays.copyOf(kinds, size * 2);
                ticks = Arrays.copyOf(ticks, size * 2);
            }
            kinds[size] = k;
            ticks[size++] = tick;
        }
    }

    private final long periodMs;
    private final double[] refs;
    private final List<Pieces> evidence = new ArrayList<>();
    private final Map<String, Kind> kinds = new HashMap<>();

    /** @param refs each belief's reference, in the order of the belief indexes used below */
    public Reasoner(long periodMs, double[] refs) {
        this.periodMs = periodMs;
        this.refs = refs.clone();
        for (int i = 0; i < refs.length; i++) {
            evidence.add(new Pieces());
        }
    }

    /** Adds a piece of evidence of ratio r to belief b at tick k. */
    public void add(int b, double r, long survivalMs, long k) {
        Kind kind = kinds.computeIfAbsent(r + "/" + survivalMs, x -> new Kind(r, survivalMs, periodMs));
        evidence.get(b).add(kind, k);
    }

    /** One live piece of evidence as saved across restarts: its ratio, survival and age. */
    public record Piece(double r, long survivalMs, long ageMs) {
    }

    /** The live evidence of belief b at tick k, oldest first. */
    public List<Piece> pieces(int b, long k) {
        Pieces p = evidence.get(b);
        List<Piece> out = new ArrayList<>(p.size);
        for (int i = 0; i < p.size; i++) {
            out.add(new Piece(p.kinds[i].r, p.kinds[i].survivalMs, (k - p.ticks[i]) * periodMs));
        }
        return out;
    }

    /** Restores a saved piece as of tick k: its age is rounded to whole ticks of this period. */
    public void restore(int b, Piece piece, long k) {
        add(b, piece.r(), piece.survivalMs(), k - Math.round((double) piece.ageMs() / periodMs));
    }

    /** {@code clears}: drops all evidence of belief b. */
    public void clear(int b) {
        Pieces p = evidence.get(b);
        Arrays.fill(p.kinds, 0, p.size, null);
        p.size = 0;
    }

    /** Number of live pieces of evidence of belief b (after the last {@link #estimate}). */
    public int evidenceCount(int b) {
        return evidence.get(b).size;
    }

    /** The estimate of belief b at tick k, dropping the evidence that has faded out. */
    public double estimate(int b, long k) {
        double lr = 1;
        Pieces p = evidence.get(b);
        int keep = 0;
        for (int i = 0; i < p.size; i++) {
            double ratio = p.kinds[i].at(k - p.ticks[i]);
            if (Double.isNaN(ratio)) {
                continue; // faded out: dropped for good
            }
            lr *= ratio;
            p.kinds[keep] = p.kinds[i];
            p.ticks[keep++] = p.ticks[i];
        }
        Arrays.fill(p.kinds, keep, p.size, null);
        p.size = keep;
        return estimate(1 / (1 + lr), refs[b]);
    }

    /** The estimate of a belief probability around a reference: ref with no evidence. */
    public static double estimate(double belief, double ref) {
        return belief < 0.5 ? 2 * belief * ref : 2 * belief * (1 - ref) + 2 * ref - 1;
    }
}
