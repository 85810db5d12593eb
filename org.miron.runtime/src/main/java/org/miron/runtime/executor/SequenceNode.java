package org.miron.runtime.executor;

import java.util.List;

/**
 * Sequence: ticks children in order from the current one; a RUNNING child makes it RUNNING (the
 * children before it are not ticked again); a FAILURE halts all and starts over next time.
 */
public class SequenceNode extends ControlNode {
    private int current;

    public SequenceNode(NodeInfo info, List<Node> children) {
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
                haltChildren();
                current = 0;
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
}
