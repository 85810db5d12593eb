package org.miron.generator;

/**
 * Keeps the objective within Gecode's 32-bit integers for every model (docs/generators.md).
 *
 * <p>A varpoint's gain is round(unit * sum_p weight_p * y_p) with weights in [0,1] (metrics are
 * checked to be in [0,1]) and utilities in [0,100], so it is at most unit * 100 * P_v for P_v
 * properties. The exact lexicographic encoding {@code tieScale * gain + tie} is used while its
 * largest value fits; beyond that the objective is the gain alone and the tie-break is left to
 * the search order (preset, then current value, first among equal gains).
 */
public final class ObjectiveScale {
    /** Gecode's Int::Limits::max: larger literals are rejected ("invalid integer literal"). */
    public static final long LIMIT = 2_147_483_646L;
    /** The usual resolution: 0.01 weighted-utility points. */
    static final double DEFAULT_UNIT = 100.0;

    /** Sum over varpoints of the properties their impacts name. */
    public final long utilityTables;
    /** Multiplier of the weighted utility before rounding; 100 unless that would overflow. */
    public final double unit;
    /** Largest possible miron_gain. */
    public final long gainBound;
    /** 3 * varpoints + 1: exceeds the largest tie sum, so one unit of gain beats every tie. */
    public final long tieScale;
    /** Whether tieScale * gain + tie fits: the exact lexicographic objective. */
    public final boolean lexicographic;

    public ObjectiveScale(AdaptationModel m) {
        this(m.varpoints.size(), m.varpoints.stream().mapToLong(vp -> vp.utilities.size()).sum());
    }

    ObjectiveScale(int varpoints, long utilityTables) {
        this.utilityTables = utilityTables;
        long perUnit = 100 * Math.max(1, utilityTables);
        this.unit = DEFAULT_UNIT * perUnit <= LIMIT ? DEFAULT_UNIT : Math.floor(1e6 * LIMIT / perUnit) / 1e6;
        this.gainBound = (long) Math.ceil(unit * 100 * utilityTables);
        this.tieScale = 3L * varpoints + 1;
        this.lexicographic = gainBound <= (LIMIT - 3L * varpoints) / tieScale;
    }

    /** The largest objective value the model can reach. */
    public long objectiveBound() {
        return lexicographic ? tieScale * gainBound + tieScale - 1 : gainBound;
    }

    /** The unit as MiniZinc source ("100.0" in the usual case). */
    public String unitText() {
        return unit == DEFAULT_UNIT ? "100.0" : Numbers.mzn(unit); // never an exponent
    }
}
