package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.MSEC;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.RunTimer;

/**
 * Timeout(msec): starts its clock on the first tick; on a later tick at which msec or more have
 * passed and the child still runs, halts the child and returns FAILURE. The clock is read at tick
 * time (not by a timer thread as in BehaviorTree.CPP), so the outcome is deterministic.
 */
public class TimeoutNode extends DecoratorNode {
    private final RunTimer timer = new RunTimer();

    public TimeoutNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        int msec = ports().requireInt(MSEC);
        boolean firstTick = timer.isIdle();
        // BT.CPP 4 starts no timer for msec="0": the child may run for ever
        boolean expires = !(isVersion4() && msec == 0);
        if (timer.elapsed(context().clock()) >= msec && !firstTick && expires) {
            timer.reset();
            resetChild();
            return NodeStatus.FAILURE;
        }
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            timer.reset();
            resetChild();
        }
        return childStatus;
    }

    @Override
    protected void onHalt() {
        timer.reset();
        super.onHalt();
    }
}
