package org.miron.runtime.executor;

/**
 * Repeat(num_cycles, -1 = forever): ticks the child again within the same tick while it succeeds,
 * up to num_cycles successes; a FAILURE gives FAILURE (and resets the count); RUNNING passes
 * through. Unlike BehaviorTree.CPP, after {@link TreeContext#maxLoopsPerTick()} child ticks in one
 * tick it returns RUNNING and resumes on the next tick, so Repeat(-1) over a child that succeeds
 * at once cannot hang the tree.
 */
public class RepeatNode extends DecoratorNode {
    public static final String NUM_CYCLES = "num_cycles";

    private int successes;

    public RepeatNode(NodeInfo info, Node child) {
        super(info, child);
    }

    @Override
    protected NodeStatus tick() {
        int cycles = ports().requireInt(NUM_CYCLES);
        if (cycles < -1) {
            throw new BtRuntimeException(path() + ": " + NUM_CYCLES + "=" + cycles + " (use -1 to repeat forever)");
        }
        setStatus(NodeStatus.RUNNING);
        int loops = 0;
        while (cycles == -1 || successes < cycles) {
            if (loops++ == context().maxLoopsPerTick()) {
                return NodeStatus.RUNNING;
            }
            NodeStatus childStatus = child.executeTick();
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            resetChild();
            if (childStatus == NodeStatus.FAILURE) {
                successes = 0;
                return NodeStatus.FAILURE;
            }
            successes++;
        }
        successes = 0;
        return NodeStatus.SUCCESS;
    }

    @Override
    protected void onHalt() {
        successes = 0;
        super.onHalt();
    }
}
