package org.miron.runtime.requirement;

/**
 * {@code eventually within D φ} at instant t: φ holds at some instant of {@code [t, t + D]} (both
 * ends included); unbounded, D reaches past any run. Decided at t once φ is known up to t + D, or as
 * soon as φ holds in the window; what stays buffered is φ over the window, no more. After the end of
 * the run, a window reaching past it with no witness is OPEN (weak end semantics).
 * {@code always within D φ} is {@code not eventually within D not φ}.
 */
final class Eventually extends FormulaNode {
    /** Past any run's length, small enough that {@code t + UNBOUNDED} cannot overflow. */
    static final long UNBOUNDED = Long.MAX_VALUE / 4;

    private final FormulaNode in;
    private final long d;
    private long end = -1; // the run's last instant, once finished

    Eventually(FormulaNode in, long withinMs) {
        this.in = in;
        // a bound past any run (within 10^20 hours: Long.MAX_VALUE ms) is as long as an unbounded
        // window and must not overflow t + D either
        this.d = Math.min(withinMs, UNBOUNDED);
    }

    @Override
    void update() {
        in.update();
        Segments s = in.out;
        long h = s.horizon();
        long decided;
        if (end >= 0) {
            decided = h;
        } else {
            int lastTrue = s.lastOf(Truth.TRUE);
            decided = Math.max(h - d, lastTrue < 0 ? Long.MIN_VALUE : s.end(lastTrue));
        }
        long t = out.horizon();
        while (t < decided && s.size() > 0) {
            long windowEnd = t + d; // inclusive
            Truth v = Truth.FALSE;
            long next = Math.min(decided, s.end(0)); // the first segment leaves the window
            for (int i = 0; i < s.size(); i++) {
                long start = s.start(i);
                if (start > windowEnd) {
                    next = Math.min(next, start - d); // a later segment enters it
                    break;
                }
                Truth x = s.value(i);
                if (x == Truth.TRUE) {
                    v = Truth.TRUE;
                } else if (x == Truth.OPEN && v == Truth.FALSE) {
                    v = Truth.OPEN;
                }
            }
            if (end >= 0 && v != Truth.TRUE) {
                if (windowEnd > end) {
                    v = Truth.OPEN; // the window reaches past the run: not a violation
                } else {
                    next = Math.min(next, end - d + 1); // from there on it will
                }
            }
            out.append(t, next, v);
            t = next;
            s.dropBefore(t);
        }
    }

    @Override
    void finish(long end) {
        in.finish(end);
        this.end = end;
        update();
    }
}
