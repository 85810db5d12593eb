package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * ReactiveSequence and ReactiveFallback (SUCCESS and FAILURE swapped): every tick starts again from
 * the first child, so earlier conditions are re-checked and a higher-priority child pre-empts a
 * running one; a RUNNING child halts the children after it; a child returning the ending status
 * (FAILURE in a sequence, SUCCESS in a fallback) halts all and ends the node with it.
 */
public final class ReactiveNode extends ControlNode {
    private final NodeStatus goOn;

    private ReactiveNode(NodeInfo info, List<Node> children, NodeStatus goOn) {
        super(info, children);
        this.goOn = goOn;
    }

    public static ReactiveNode sequence(NodeInfo info, List<Node> children) {
        return new ReactiveNode(info, children, NodeStatus.SUCCESS);
    }

    public static ReactiveNode fallback(NodeInfo info, List<Node> children) {
        return new ReactiveNode(info, children, NodeStatus.FAILURE);
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
            if (childStatus != goOn) {
                haltChildren();
                return childStatus;
            }
        }
        haltChildren();
        return goOn;
    }
}
