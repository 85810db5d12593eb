package org.miron.runtime.executor;

/** ForceSuccess: any finished status becomes SUCCESS; RUNNING passes through. */
public class ForceSuccessNode extends DecoratorNode {

    public ForceSuccessNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
            return NodeStatus.SUCCESS;
        }
        return childStatus;
    }
}
