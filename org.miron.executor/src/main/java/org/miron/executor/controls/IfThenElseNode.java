package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * IfThenElse (BehaviorTree.CPP 3.8): ticks the condition until it finishes; SUCCESS picks the
 * then-branch, FAILURE the else-branch, or ends the node with FAILURE when there is none. Not
 * reactive: once a branch is picked it runs to the end without the condition being ticked again.
 * The branch's finished status ends the node, which then halts its children and starts over, as
 * halting it from outside does. RUNNING of the condition passes through.
 */
public final class IfThenElseNode extends ConditionalNode {
    /** The branch picked by the condition (THEN or ELSE), or CONDITION while undecided. */
    private int branch = CONDITION;

    public IfThenElseNode(NodeInfo info, List<Node> children) {
        super(info, children, "IfThenElse");
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        if (branch == CONDITION) {
            NodeStatus condition = tickChild(CONDITION);
            if (condition == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            if (condition == NodeStatus.SUCCESS) {
                branch = THEN;
            } else if (hasElse()) {
                branch = ELSE;
            } else {
                haltChildren();
                return NodeStatus.FAILURE;
            }
        }
        NodeStatus result = tickChild(branch);
        if (result == NodeStatus.RUNNING) {
            return NodeStatus.RUNNING;
        }
        haltChildren();
        branch = CONDITION;
        return result;
    }

    @Override
    protected void onHalt() {
        branch = CONDITION;
        super.onHalt();
    }

    /** The running branch (1 then, 2 else), 0 while the condition decides (for tests and monitors). */
    public int currentBranch() {
        return branch;
    }
}
