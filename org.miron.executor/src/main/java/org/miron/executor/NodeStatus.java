package org.miron.executor;

/**
 * Status of a behaviour-tree node, as in BehaviorTree.CPP. SKIPPED exists in version 4 only: a node
 * whose pre-condition skipped it returns it to its parent but stays IDLE itself.
 */
public enum NodeStatus {
    IDLE, RUNNING, SUCCESS, FAILURE, SKIPPED;

    /** SUCCESS or FAILURE: the node has finished. */
    public boolean isCompleted() {
        return this == SUCCESS || this == FAILURE;
    }
}
