package org.miron.executor.trace;

import org.miron.executor.Node;
import org.miron.executor.NodeStatus;

/** Told of every status change of every node, on the ticking thread, as it happens. */
@FunctionalInterface
public interface StatusListener {
    void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to);
}
