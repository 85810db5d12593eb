package org.miron.executor.decorators;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** ForceSuccess / ForceFailure: any finished status of the child becomes the forced one; RUNNING passes through. */
public final class ForceNode extends DecoratorNode {
    private final NodeStatus forced;

    public ForceNode(NodeInfo info, Node child, NodeStatus forced) {
        super(info, child);
        this.forced = forced;
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
            return forced;
        }
        return childStatus;
    }
}
