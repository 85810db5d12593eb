package org.miron.runtime.executor;

/**
 * Timeout(msec): starts its clock on the first tick; on a later tick at which msec or more have
 * passed and the child still runs, halts the child and returns FAILURE. The clock is read at tick
 * time (not by a timer thread as in BehaviorTree.CPP), so the outcome is deterministic.
 */
public class TimeoutNode extends DecoratorNode {
    public static final String MSEC = "msec";

    private boolean started;
    private long startMillis;

    public TimeoutNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        int msec = ports().requireInt(MSEC);
        long now = context().clock().nowMillis();
        if (!started) {
            started = true;
            startMillis = now;
        } else if (now - startMillis >= msec) {
            started = false;
            resetChild();
            return NodeStatus.FAILURE;
        }
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            started = false;
            resetChild();
        }
        return childStatus;
    }

    @Override
    protected void onHalt() {
        started = false;
        super.onHalt();
    }
}
