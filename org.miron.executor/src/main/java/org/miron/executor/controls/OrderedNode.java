package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * Sequence, Fallback and their Star (memory) variants: one algorithm with SUCCESS and FAILURE
 * swapped. Children are ticked in order from the current one while they return the status that
 * lets the node go on (SUCCESS in a Sequence, FAILURE in a Fallback); a RUNNING child makes the
 * node RUNNING and the children before it are not ticked again; the other status ends the node
 * with that status. Then a plain node halts all and starts over next time, while a Star node keeps
 * its position so the next tick resumes at that child. Going through all children gives the
 * go-on status. Halting always resets. (FallbackStar is in the seed's metamodel though
 * BehaviorTree.CPP 3 no longer registers it.)
 */
public final class OrderedNode extends ControlNode {
    private final NodeStatus goOn;
    private final boolean memory;
    private int current;

    private OrderedNode(NodeInfo info, List<Node> children, NodeStatus goOn, boolean memory) {
        super(info, children);
        this.goOn = goOn;
        this.memory = memory;
    }

    public static OrderedNode sequence(NodeInfo info, List<Node> children) {
        return new OrderedNode(info, children, NodeStatus.SUCCESS, false);
    }

    public static OrderedNode sequenceStar(NodeInfo info, List<Node> children) {
        return new OrderedNode(info, children, NodeStatus.SUCCESS, true);
    }

    public static OrderedNode fallback(NodeInfo info, List<Node> children) {
        return new OrderedNode(info, children, NodeStatus.FAILURE, false);
    }

    public static OrderedNode fallbackStar(NodeInfo info, List<Node> children) {
        return new OrderedNode(info, children, NodeStatus.FAILURE, true);
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        while (current < children.size()) {
            NodeStatus childStatus = tickChild(current);
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            if (childStatus != goOn) {
                if (memory) {
                    haltChildrenFrom(current); // keep `current`: earlier children are not ticked again
                } else {
                    haltChildren();
                    current = 0;
                }
                return childStatus;
            }
            current++;
        }
        haltChildren();
        current = 0;
        return goOn;
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
