package org.miron.executor.trace;

import org.miron.executor.Node;
import org.miron.executor.NodeStatus;

/**
 * Asked on the ticking thread before a node that has not finished is ticked, once no version-4
 * pre-condition decided (BehaviorTree.CPP's pre-tick callback, which Groot2's breakpoints use).
 * SUCCESS or FAILURE replaces the node's tick; anything else (null, SKIPPED) lets it tick. The
 * hook may block: only the ticking thread waits.
 */
@FunctionalInterface
public interface TickHook {
    NodeStatus beforeTick(Node node);
}
