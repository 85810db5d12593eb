package org.miron.runtime.executor;

import java.util.List;

/**
 * FallbackStar (fallback with memory), the mirror of SequenceStar: after a SUCCESS it keeps its
 * position, so the next tick re-ticks the child that succeeded rather than the ones that failed
 * before it. BehaviorTree.CPP 3 no longer registers it; the seed's metamodel has it.
 */
public class FallbackStarNode extends ControlNode {
    private int current;

    public FallbackStarNode(NodeInfo info, List<Node> children) {
        super(info, children);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        while (current < children.size()) {
            NodeStatus childStatus = tickChild(current);
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            if (childStatus == NodeStatus.SUCCESS) {
                haltChildrenFrom(current);
                return NodeStatus.SUCCESS;
            }
            current++;
        }
        haltChildren();
        current = 0;
        return NodeStatus.FAILURE;
    }

    @Override
    protected void onHalt() {
        current = 0;
        super.onHalt();
    }

    public int currentChild() {
        return current;
    }
}
