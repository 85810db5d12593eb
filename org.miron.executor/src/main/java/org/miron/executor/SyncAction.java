package org.miron.executor;

/** A Java action (or condition) that finishes within its tick: SUCCESS or FAILURE, never RUNNING. */
@FunctionalInterface
public interface SyncAction {
    NodeStatus tick(Ports ports);
}
