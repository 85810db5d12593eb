package org.miron.executor.decorators;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * KeepRunningUntilFailure (BehaviorTree.CPP 3): a SUCCESS of the child becomes RUNNING (the child
 * is reset and starts again on the next tick), a FAILURE ends the node with FAILURE.
 */
public final class KeepRunningUntilFailureNode extends DecoratorNode {

    public KeepRunningUntilFailureNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
        }
        return childStatus == NodeStatus.FAILURE ? NodeStatus.FAILURE : NodeStatus.RUNNING;
    }
}
