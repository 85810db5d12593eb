package org.miron.executor;

/**
 * A Java action that may take several ticks (BehaviorTree.CPP's StatefulActionNode): it returns
 * RUNNING until it is done and is told when it is halted while running. One instance per tree
 * node, so it may keep state.
 */
public interface AsyncAction {

    /** First tick (the node was not running): start the work, return its status. */
    NodeStatus onStart(Ports ports);

    /** Later ticks while RUNNING: report progress. */
    NodeStatus onRunning(Ports ports);

    /** The node was halted while RUNNING: stop the work. */
    void onHalted();
}
