package org.miron.runtime.roqme.expr;

/**
 * A compiled pattern: evaluated once per step in which one of the slots its observation reads was
 * updated, it says whether the pattern occurs in that step. Nodes keep their own state (last value,
 * pending left side, counters), so every node of a pattern is evaluated at each such step.
 */
public interface EventNode {
    boolean occurs(Store s);
}
