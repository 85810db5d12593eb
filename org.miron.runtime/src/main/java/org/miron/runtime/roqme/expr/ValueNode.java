package org.miron.runtime.roqme.expr;

/** A compiled value expression; {@code null} is unknown and propagates (docs/roqme-provider.md). */
@FunctionalInterface
public interface ValueNode {
    Object eval(Store s);
}
