package org.miron.runtime.requirement;

/**
 * A state formula: a RoQME expression over the signals' current values, evaluated by the engine's
 * expression pool. OPEN while a signal it reads has no value. Its segments are appended by
 * {@link Signals} as instants close; it has no inputs of its own to pull.
 */
final class Atom extends FormulaNode {
    final int node;
    final int[] reads;
    Truth value = Truth.OPEN;
    boolean dirty = true;
    /** Its requirement: once that is decided the atom is no longer extended. */
    RequirementMonitor owner;

    Atom(int node, int[] reads) {
        this.node = node;
        this.reads = reads;
    }

    @Override
    void update() {
    }

    @Override
    void finish(long end) {
        if (out.horizon() < end + 1) {
            out.append(out.horizon(), end + 1, value);
        }
    }
}
