package org.miron.runtime.executor;

import java.util.List;

/**
 * SequenceStar (sequence with memory): like Sequence, but after a FAILURE it keeps its position,
 * so the next tick retries the failed child instead of starting over. Halting a running one resets it.
 */
public class SequenceStarNode extends ControlNode {
    private int current;

    public SequenceStarNode(NodeInfo info, List<Node> children) {
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
            if (childStatus == NodeStatus.FAILURE) {
                // keep `current`: the children before it are not ticked again
                haltChildrenFrom(current);
                return NodeStatus.FAILURE;
            }
            current++;
        }
        haltChildren();
        current = 0;
        return NodeStatus.SUCCESS;
    }

    @Override
    protected void onHalt() {
        current = 0;
        super.onHalt();
    }

    /** Index of the child the next tick starts from (for tests and monitors). */
    public int currentChild() {
        return current;
    }
}
