package org.miron.runtime.executor;

import java.util.List;

/**
 * ReactiveSequence: re-ticks from the first child on every tick, so earlier conditions are checked
 * again; a RUNNING child halts the children after it; a FAILURE halts all.
 */
public class ReactiveSequenceNode extends ControlNode {

    public ReactiveSequenceNode(NodeInfo info, List<Node> children) {
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
            if (childStatus == NodeStatus.FAILURE) {
                haltChildren();
                return NodeStatus.FAILURE;
            }
        }
        haltChildren();
        return NodeStatus.SUCCESS;
    }
}
