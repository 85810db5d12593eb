package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * WhileDoElse (BehaviorTree.CPP 3.8), the reactive IfThenElse: the condition is ticked on every
 * tick; SUCCESS ticks the then-branch after halting the else-branch, FAILURE the else-branch after
 * halting the then-branch (without an else-branch: FAILURE). So a branch the condition leaves is
 * halted. A finished branch ends the node and all children are halted; RUNNING of the condition
 * passes through and leaves a running branch as it is.
 */
public final class WhileDoElseNode extends ConditionalNode {

    public WhileDoElseNode(NodeInfo info, List<Node> children) {
        super(info, children, "WhileDoElse");
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus condition = tickChild(CONDITION);
        if (condition == NodeStatus.RUNNING) {
            return NodeStatus.RUNNING;
        }
        NodeStatus result;
        if (condition == NodeStatus.SUCCESS) {
            if (hasElse()) {
                haltChild(ELSE);
            }
            result = tickChild(THEN);
        } else if (hasElse()) {
            haltChild(THEN);
            result = tickChild(ELSE);
        } else {
            result = NodeStatus.FAILURE;
        }
        if (result == NodeStatus.RUNNING) {
            return NodeStatus.RUNNING;
        }
        haltChildren();
        return result;
    }
}
