package org.miron.runtime.executor;

/** ForceFailure: any finished status becomes FAILURE; RUNNING passes through. */
public class ForceFailureNode extends DecoratorNode {

    public ForceFailureNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
            return NodeStatus.FAILURE;
        }
        return childStatus;
    }
}
