package org.miron.runtime.executor;

import java.util.List;

/**
 * Fallback: ticks children in order from the current one until one does not fail; a RUNNING child
 * makes it RUNNING; a SUCCESS halts all and starts over next time; all FAILURE gives FAILURE.
 */
public class FallbackNode extends ControlNode {
    private int current;

    public FallbackNode(NodeInfo info, List<Node> children) {
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
                haltChildren();
                current = 0;
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
}
