package org.miron.executor;

/** Leaf running an {@link AsyncAction}: onStart when it was not running, onRunning after, onHalted on halt. */
public class AsyncActionNode extends Node {
    private final AsyncAction action;

    public AsyncActionNode(NodeInfo info, AsyncAction action) {
        super(info);
        this.action = action;
    }

    @Override
    protected NodeStatus tick() {
        return status() == NodeStatus.RUNNING ? action.onRunning(ports()) : action.onStart(ports());
    }

    @Override
    protected void onHalt() {
        action.onHalted();
    }

    public AsyncAction action() {
        return action;
    }
}
