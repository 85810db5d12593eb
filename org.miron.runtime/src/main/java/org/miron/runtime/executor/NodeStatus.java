package org.miron.runtime.executor;

/** Status of a behaviour-tree node, as in BehaviorTree.CPP 3. */
public enum NodeStatus {
    IDLE, RUNNING, SUCCESS, FAILURE;

    /** SUCCESS or FAILURE: the node has finished. */
    public boolean isCompleted() {
        return this == SUCCESS || this == FAILURE;
    }
}
