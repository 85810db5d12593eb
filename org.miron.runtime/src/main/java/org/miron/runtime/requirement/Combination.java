package org.miron.runtime.requirement;

/** {@code not}, {@code and}, {@code or}, {@code implies}: pointwise, in Kleene's logic. */
final class Combination extends FormulaNode {
    enum Op { NOT, AND, OR, IMPLIES }

    private final Op op;
    private final FormulaNode a;
    private final FormulaNode b; // null for NOT

    Combination(Op op, FormulaNode a, FormulaNode b) {
        this.op = op;
        this.a = a;
        this.b = b;
    }

    @Override
    void update() {
        a.update();
        if (b != null) {
            b.update();
        }
        long h = b == null ? a.out.horizon() : Math.min(a.out.horizon(), b.out.horizon());
        long t = out.horizon();
        while (t < h) {
            // after dropBefore(t) each input's first segment is the one holding t
            long next = Math.min(h, a.out.end(0));
            Truth x = a.out.value(0);
            Truth v;
            if (b == null) {
                v = x.not();
            } else {
                next = Math.min(next, b.out.end(0));
                Truth y = b.out.value(0);
                v = switch (op) {
                    case AND -> x.and(y);
                    case OR -> x.or(y);
                    default -> x.not().or(y);
                };
            }
            out.append(t, next, v);
            t = next;
            a.out.dropBefore(t);
            if (b != null) {
                b.out.dropBefore(t);
            }
        }
    }

    @Override
    void finish(long end) {
        a.finish(end);
        if (b != null) {
            b.finish(end);
        }
        update();
    }
}
