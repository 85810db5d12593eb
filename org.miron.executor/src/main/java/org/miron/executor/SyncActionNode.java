package org.miron.executor;

/** Leaf running a {@link SyncAction}; a RUNNING result is an error, as for BehaviorTree.CPP's SyncActionNode. */
public class SyncActionNode extends Node {
    private final SyncAction action;

    public SyncActionNode(NodeInfo info, SyncAction action) {
        super(info);
        this.action = action;
    }

    @Override
    protected NodeStatus tick() {
        NodeStatus result = action.tick(ports());
        if (result == NodeStatus.RUNNING) {
            throw new BtRuntimeException(path() + ": a synchronous action or condition must not return RUNNING"
                    + " (register it as an AsyncAction)");
        }
        return result;
    }
}
