package org.miron.runtime.requirement;

/**
 * A sub-formula's truth over time, computed online: {@link #update()} extends {@link #out} as far
 * as its inputs decide it; {@link #finish(long)} says the run ended at {@code end} (its last
 * instant), after which every instant up to {@code end} is decided, OPEN where a window reached past
 * the end. Each node has one reader, which drops from {@code out} what it has consumed.
 */
abstract class FormulaNode {
    final Segments out = new Segments();

    abstract void update();

    abstract void finish(long end);
}
