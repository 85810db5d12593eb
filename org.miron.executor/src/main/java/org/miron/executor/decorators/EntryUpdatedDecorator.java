package org.miron.executor.decorators;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.actions.EntryUpdatedNode;

/**
 * SkipUnlessUpdated and WaitValueUpdate(entry) (BT.CPP 4): tick the child only when the entry was
 * written since the node last looked, else return SKIPPED (SkipUnlessUpdated) or RUNNING
 * (WaitValueUpdate); a child that runs is ticked on without looking again. Halting halts the
 * child (BT.CPP 4.8 forgets to).
 */
public final class EntryUpdatedDecorator extends DecoratorNode {
    private final String key;
    private final NodeStatus ifNotUpdated;
    private long seen;
    private boolean childRunning;

    public EntryUpdatedDecorator(NodeInfo info, Node child, NodeStatus ifNotUpdated) {
        super(info, child);
        this.key = EntryUpdatedNode.entryKey(info);
        this.ifNotUpdated = ifNotUpdated;
    }

    @Override
    protected NodeStatus tick() {
        if (!childRunning) {
            long writes = ports().blackboard().writeCount(key);
            if (writes < 0) {
                return ifNotUpdated;
            }
            boolean updated = writes != seen;
            seen = writes;
            if (!updated) {
                return ifNotUpdated;
            }
        }
        NodeStatus status = child.executeTick();
        childRunning = status == NodeStatus.RUNNING;
        return status;
    }

    @Override
    protected void onHalt() {
        childRunning = false;
        super.onHalt();
    }
}
