package org.miron.runtime.executor;

/** Told of every status change of every node, on the ticking thread, as it happens. */
@FunctionalInterface
public interface StatusListener {
    void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to);
}
