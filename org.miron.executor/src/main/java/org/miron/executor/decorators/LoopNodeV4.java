package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.NUM_ATTEMPTS;
import static org.miron.bt.nodes.BuiltinNodes.NUM_CYCLES;

import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;

/**
 * Version-4 Repeat(num_cycles) and RetryUntilSuccessful(num_attempts) (BT.CPP 4's repeat_node and
 * retry_node): as {@link LoopNode}, but a child that finished with the looping status within one
 * tick is not ticked again in the same tick: the node returns RUNNING and asks for a wake-up, so
 * the whole tree is ticked again at once ({@link Tree#tickRoot()}). A SKIPPED child skips the
 * node, keeping the count. Retry re-reads num_attempts after each failure.
 */
public final class LoopNodeV4 extends DecoratorNode {
    private final NodeStatus loopOn;
    private final String countPort;
    private int loops;

    private LoopNodeV4(NodeInfo info, Node child, NodeStatus loopOn, String countPort) {
        super(info, child);
        this.loopOn = loopOn;
        this.countPort = countPort;
    }

    public static LoopNodeV4 repeat(NodeInfo info, Node child) {
        return new LoopNodeV4(info, child, NodeStatus.SUCCESS, NUM_CYCLES);
    }

    public static LoopNodeV4 retry(NodeInfo info, Node child) {
        return new LoopNodeV4(info, child, NodeStatus.FAILURE, NUM_ATTEMPTS);
    }

    @Override
    protected NodeStatus tick() {
        int count = ports().requireInt(countPort);
        boolean again = loops < count || count == -1;
        setStatus(NodeStatus.RUNNING);
        while (again) {
            NodeStatus before = child.status();
            NodeStatus childStatus = child.executeTick();
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            if (childStatus == NodeStatus.SKIPPED) {
                resetChild();
                return NodeStatus.SKIPPED;
            }
            resetChild();
            if (childStatus != loopOn) {
                loops = 0;
                return childStatus;
            }
            loops++;
            if (loopOn == NodeStatus.FAILURE) {
                count = ports().getInt(countPort).orElse(count);
            }
            again = loops < count || count == -1;
            if (before == NodeStatus.IDLE && again) {
                context().emitWakeUp();
                return NodeStatus.RUNNING;
            }
        }
        loops = 0;
        return loopOn;
    }

    @Override
    protected void onHalt() {
        loops = 0;
        super.onHalt();
    }
}
