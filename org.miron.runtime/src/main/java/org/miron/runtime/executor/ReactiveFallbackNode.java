package org.miron.runtime.executor;

import java.util.List;

/**
 * ReactiveFallback: re-ticks from the first child on every tick, so a higher-priority child that
 * starts succeeding pre-empts a running one; a RUNNING child halts the children after it.
 */
public class ReactiveFallbackNode extends ControlNode {

    public ReactiveFallbackNode(NodeInfo info, List<Node> children) {
        super(info, children);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        for (int i = 0; i < children.size(); i++) {
            NodeStatus childStatus = tickChild(i);
            if (childStatus == NodeStatus.RUNNING) {
                haltChildrenFrom(i + 1);
                return NodeStatus.RUNNING;
            }
            if (childStatus == NodeStatus.SUCCESS) {
                haltChildren();
                return NodeStatus.SUCCESS;
            }
        }
        haltChildren();
        return NodeStatus.FAILURE;
    }
}
