package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.DELAY_MSEC;

import org.miron.executor.BtRuntimeException;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.RunTimer;

/**
 * Delay(delay_msec) (BehaviorTree.CPP 3.8): RUNNING until delay_msec have passed since its first
 * tick, then ticks the child on every tick and returns its status; once the child finishes, the
 * next tick starts a new delay. delay_msec is read on the first tick of each run. As with Timeout,
 * the clock is read at tick time (BT.CPP uses a timer thread), so a run is deterministic.
 */
public final class DelayNode extends DecoratorNode {
    private final RunTimer timer = new RunTimer();
    private int delayMsec;

    public DelayNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        if (timer.isIdle()) {
            delayMsec = ports().requireInt(DELAY_MSEC);
            if (delayMsec < 0) {
                throw new BtRuntimeException(path() + ": " + DELAY_MSEC + "=" + delayMsec + " (must be at least 0)");
            }
        }
        setStatus(NodeStatus.RUNNING);
        if (timer.elapsed(context().clock()) < delayMsec) {
            return NodeStatus.RUNNING;
        }
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
