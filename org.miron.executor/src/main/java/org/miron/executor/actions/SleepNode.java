package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.MSEC;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.RunTimer;

/**
 * Sleep(msec) (BT.CPP 4): RUNNING until msec have passed since its first tick, then SUCCESS;
 * msec = 0 succeeds at once. Like Timeout and Delay it reads the clock when ticked (BT.CPP uses a
 * timer thread), so a run is deterministic.
 */
public final class SleepNode extends Node {
    private final RunTimer timer = new RunTimer();
    private int msec;

    public SleepNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        if (status() != NodeStatus.RUNNING) {
            msec = ports().requireInt(MSEC);
            if (msec <= 0) {
                return NodeStatus.SUCCESS;
            }
            timer.reset();
            timer.elapsed(context().clock());
            return NodeStatus.RUNNING;
        }
        if (timer.elapsed(context().clock()) >= msec) {
            timer.reset();
            return NodeStatus.SUCCESS;
        }
        return NodeStatus.RUNNING;
    }

    @Override
    protected void onHalt() {
        timer.reset();
    }
}
