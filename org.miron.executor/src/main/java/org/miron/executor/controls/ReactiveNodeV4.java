package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * Version-4 ReactiveSequence and ReactiveFallback (BT.CPP 4): every tick starts again from the
 * first child; a RUNNING child halts every other child (before and after it) and makes the node
 * RUNNING; the ending status (FAILURE in a sequence, SUCCESS in a fallback) halts all and ends the
 * node; a SKIPPED child is reset so it can be skipped again, and a node whose children were all
 * skipped is SKIPPED.
 */
public final class ReactiveNodeV4 extends ControlNode {
    private final NodeStatus goOn;

    private ReactiveNodeV4(NodeInfo info, List<Node> children, NodeStatus goOn) {
        super(info, children);
        this.goOn = goOn;
    }

    public static ReactiveNodeV4 sequence(NodeInfo info, List<Node> children) {
        return new ReactiveNodeV4(info, children, NodeStatus.SUCCESS);
    }

    public static ReactiveNodeV4 fallback(NodeInfo info, List<Node> children) {
        return new ReactiveNodeV4(info, children, NodeStatus.FAILURE);
    }

    @Override
    protected NodeStatus tick() {
        boolean allSkipped = true;
        setStatus(NodeStatus.RUNNING);
        for (int i = 0; i < children.size(); i++) {
            NodeStatus childStatus = tickChild(i);
            allSkipped &= childStatus == NodeStatus.SKIPPED;
            if (childStatus == NodeStatus.RUNNING) {
                for (int j = 0; j < children.size(); j++) {
                    if (j != i) {
                        haltChild(j);
                    }
                }
                return NodeStatus.RUNNING;
            }
            if (childStatus == NodeStatus.SKIPPED) {
                haltChild(i);
            } else if (childStatus != goOn) {
                haltChildren();
                return childStatus;
            }
        }
        haltChildren();
        return allSkipped ? NodeStatus.SKIPPED : goOn;
    }
}
