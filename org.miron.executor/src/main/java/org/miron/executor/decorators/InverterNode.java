package org.miron.executor.decorators;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** Inverter: swaps SUCCESS and FAILURE; RUNNING passes through. */
public class InverterNode extends DecoratorNode {

    public InverterNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        switch (childStatus) {
            case SUCCESS:
                resetChild();
                return NodeStatus.FAILURE;
            case FAILURE:
                resetChild();
                return NodeStatus.SUCCESS;
            default:
                return childStatus;
        }
    }
}
