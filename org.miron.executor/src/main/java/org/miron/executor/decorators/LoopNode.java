package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.NUM_ATTEMPTS;
import static org.miron.bt.nodes.BuiltinNodes.NUM_CYCLES;

import org.miron.executor.BtRuntimeException;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.TreeContext;

/**
 * Repeat(num_cycles) and RetryUntilSuccessful(num_attempts), both spellings: one loop with SUCCESS
 * and FAILURE swapped. The child is ticked again within the same tick while it returns the looping
 * status (SUCCESS for Repeat, FAILURE for Retry), up to the count (-1 = forever); the other status
 * ends the node with it; a used-up count ends it with the looping status (all cycles done: Repeat
 * succeeds; all attempts failed: Retry fails); RUNNING passes through. Unlike BehaviorTree.CPP, after {@link TreeContext#maxLoopsPerTick()} child
 * ticks in one tick it returns RUNNING and resumes on the next tick, so Repeat(-1) over a child that
 * succeeds at once cannot hang the tree.
 */
public final class LoopNode extends DecoratorNode {
    private final NodeStatus loopOn;
    private final String countPort;
    private int loops;

    private LoopNode(NodeInfo info, Node child, NodeStatus loopOn, String countPort) {
        super(info, child);
        this.loopOn = loopOn;
        this.countPort = countPort;
    }

    public static LoopNode repeat(NodeInfo info, Node child) {
        return new LoopNode(info, child, NodeStatus.SUCCESS, NUM_CYCLES);
    }

    public static LoopNode retry(NodeInfo info, Node child) {
        return new LoopNode(info, child, NodeStatus.FAILURE, NUM_ATTEMPTS);
    }

    @Override
    protected NodeStatus tick() {
        int count = ports().requireInt(countPort);
        if (count < -1) {
            throw new BtRuntimeException(path() + ": " + countPort + "=" + count + " (use -1 for forever)");
        }
        setStatus(NodeStatus.RUNNING);
        int ticks = 0;
        while (count == -1 || loops < count) {
            if (ticks++ == context().maxLoopsPerTick()) {
                return NodeStatus.RUNNING;
            }
            NodeStatus childStatus = child.executeTick();
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            resetChild();
            if (childStatus != loopOn) {
                loops = 0;
                return childStatus;
            }
            loops++;
        }
        loops = 0;
        // Repeat has done all its cycles (SUCCESS); Retry has used up its attempts (FAILURE).
        return loopOn;
    }

    @Override
    protected void onHalt() {
        loops = 0;
        super.onHalt();
    }
}
