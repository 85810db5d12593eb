package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * Version-4 Sequence, Fallback, SequenceWithMemory, AsyncSequence and AsyncFallback (BT.CPP 4's
 * sequence_node, fallback_node and sequence_with_memory_node): {@link OrderedNode}'s algorithm
 * plus SKIPPED children, which are passed over (a node whose children were all skipped is SKIPPED
 * itself). SequenceWithMemory keeps its place after a FAILURE, halting only the children from the
 * failed one on. SequenceWithMemory, AsyncSequence and AsyncFallback yield after each child that
 * finished within one tick: they return RUNNING and ask for a wake-up, so the tree is ticked
 * again at once from the root.
 */
public final class OrderedNodeV4 extends ControlNode {
    private final NodeStatus goOn;
    private final boolean memory;
    private final boolean yields;
    private int current;
    private int skipped;

    private OrderedNodeV4(NodeInfo info, List<Node> children, NodeStatus goOn, boolean memory, boolean yields) {
        super(info, children);
        this.goOn = goOn;
        this.memory = memory;
        this.yields = yields;
    }

    public static OrderedNodeV4 sequence(NodeInfo info, List<Node> children, boolean async) {
        return new OrderedNodeV4(info, children, NodeStatus.SUCCESS, false, async);
    }

    public static OrderedNodeV4 fallback(NodeInfo info, List<Node> children, boolean async) {
        return new OrderedNodeV4(info, children, NodeStatus.FAILURE, false, async);
    }

    public static OrderedNodeV4 sequenceWithMemory(NodeInfo info, List<Node> children) {
        return new OrderedNodeV4(info, children, NodeStatus.SUCCESS, true, true);
    }

    @Override
    protected NodeStatus tick() {
        if (status() != NodeStatus.RUNNING && status() != NodeStatus.SUCCESS && status() != NodeStatus.FAILURE) {
            skipped = 0;
        }
        setStatus(NodeStatus.RUNNING);
        int n = children.size();
        while (current < n) {
            NodeStatus before = children.get(current).status();
            NodeStatus childStatus = tickChild(current);
            if (childStatus == NodeStatus.RUNNING) {
                return NodeStatus.RUNNING;
            }
            if (childStatus == NodeStatus.SKIPPED) {
                current++;
                skipped++;
                continue;
            }
            if (childStatus != goOn) {
                if (memory) {
                    haltChildrenFrom(current); // keep `current`: earlier children are not ticked again
                } else {
                    haltChildren();
                    current = 0;
                }
                return childStatus;
            }
            current++;
            if (yields && before == NodeStatus.IDLE && current < n) {
                context().emitWakeUp();
                return NodeStatus.RUNNING;
            }
        }
        boolean allSkipped = skipped == n;
        haltChildren();
        current = 0;
        skipped = 0;
        return allSkipped ? NodeStatus.SKIPPED : goOn;
    }

    @Override
    protected void onHalt() {
        if (!memory) {
            current = 0;
            skipped = 0;
        }
        super.onHalt();
    }

    /** Index of the child the next tick starts from (for tests and monitors). */
    public int currentChild() {
        return current;
    }
}
