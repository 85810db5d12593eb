package org.miron.executor.controls;

import static org.miron.bt.nodes.BuiltinNodes.MAX_FAILURES;

import java.util.Arrays;
import java.util.List;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * ParallelAll(max_failures = 1) (BT.CPP 4): ticks every child until all have finished (or been
 * skipped), then FAILURE if at least max_failures of them failed (negative: counted from the
 * number of children), else SUCCESS. All children skipped: SKIPPED.
 */
public final class ParallelAllNode extends ControlNode {
    private final boolean[] finished;
    private int failures;

    public ParallelAllNode(NodeInfo info, List<Node> children) {
        super(info, children);
        finished = new boolean[children.size()];
    }

    @Override
    protected NodeStatus tick() {
        int n = children.size();
        int written = ports().getInt(MAX_FAILURES).orElse(1);
        int threshold = written < 0 ? Math.max(n + written + 1, 0) : written;
        if (threshold > n) {
            throw new BtRuntimeException(path() + ": " + MAX_FAILURES + "=" + written + " but there are only " + n + " children");
        }
        setStatus(NodeStatus.RUNNING);
        int skipped = 0;
        int done = 0;
        for (int i = 0; i < n; i++) {
            if (finished[i]) {
                done++;
                continue;
            }
            NodeStatus childStatus = tickChild(i);
            if (childStatus == NodeStatus.SKIPPED) {
                skipped++;
            } else if (childStatus.isCompleted()) {
                finished[i] = true;
                done++;
                if (childStatus == NodeStatus.FAILURE) {
                    failures++;
                }
            }
        }
        if (skipped == n) {
            return NodeStatus.SKIPPED;
        }
        if (skipped + done >= n) {
            haltChildren();
            NodeStatus result = failures >= threshold ? NodeStatus.FAILURE : NodeStatus.SUCCESS;
            Arrays.fill(finished, false);
            failures = 0;
            return result;
        }
        return NodeStatus.RUNNING;
    }

    @Override
    protected void onHalt() {
        Arrays.fill(finished, false);
        failures = 0;
        super.onHalt();
    }
}
