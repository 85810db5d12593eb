package org.miron.runtime.executor;

/**
 * RetryUntilSuccessful / RetryUntilSuccesful (num_attempts, -1 = forever): ticks the child again
 * within the same tick while it fails, up to num_attempts attempts; SUCCESS gives SUCCESS, attempts
 * used up give FAILURE; RUNNING passes through. Bounded per tick like {@link RepeatNode}.
 */
public class RetryNode extends DecoratorNode {
    public static final String NUM_ATTEMPTS = "num_attempts";

    private int failures;

    public RetryNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        int attempts = ports().requireInt(NUM_ATTEMPTS);
        if (attempts < -1) {
            throw new BtRuntimeException(path() + ": " + NUM_ATTEMPTS + "=" + attempts + " (use -1 to retry forever)");
        }
        setStatus(NodeStatus.RUNNING);
        int loops = 0;
        while (attempts == -1 || failures < attempts) {
            if (loops++ == context().maxLoopsPerTick()) {
                return NodeStatus.RUNNING;
            }
            NodeStatus childStatus = child.executeTick();
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            resetChild();
            if (childStatus == NodeStatus.SUCCESS) {
                failures = 0;
                return NodeStatus.SUCCESS;
            }
            failures++;
        }
        failures = 0;
        return NodeStatus.FAILURE;
    }

    @Override
    protected void onHalt() {
        failures = 0;
        super.onHalt();
    }
}
