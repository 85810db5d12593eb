package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.THEN_SKIP;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * RunOnce(then_skip = true) (BT.CPP 4): ticks its child until it finishes once; afterwards the
 * node is SKIPPED (then_skip) or returns that first result again, without ticking the child.
 */
public final class RunOnceNode extends DecoratorNode {
    private boolean done;
    private NodeStatus result;

    public RunOnceNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        boolean skip = ports().getBoolean(THEN_SKIP).orElse(true);
        if (done) {
            return skip ? NodeStatus.SKIPPED : result;
        }
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            done = true;
            result = childStatus;
            resetChild();
        }
        return childStatus;
    }
}
