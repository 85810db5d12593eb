package org.miron.executor.controls;

import static org.miron.bt.nodes.BuiltinNodes.FAILURE_THRESHOLD;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_THRESHOLD;

import java.util.List;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * Parallel(success_threshold, failure_threshold=1): ticks every child that has not finished yet
 * and remembers the finished ones; SUCCESS once success_threshold children succeeded, FAILURE once
 * failure_threshold failed or success can no longer be reached; then halts all children.
 * A negative threshold counts from the number of children: -1 means all of them, -2 all but one.
 */
public class ParallelNode extends ControlNode {
    private final boolean[] finished;
    private int successes;
    private int failures;

    public ParallelNode(NodeInfo info, List<Node> children) {
        super(info, children);
        finished = new boolean[children.size()];
    }

    /** Resolves a threshold as written (maybe negative) against the number of children. */
    public static int resolveThreshold(String port, int written, int childCount) {
        int threshold = written < 0 ? childCount + written + 1 : written;
        if (threshold < 1 || threshold > childCount) {
            throw new BtRuntimeException(port + "=" + written + " must resolve to 1.." + childCount
                    + " with " + childCount + " children (negative values count from the number of children)");
        }
        return threshold;
    }

    @Override
    protected NodeStatus tick() {
        int n = children.size();
        int successThreshold = resolveThreshold(SUCCESS_THRESHOLD, ports().requireInt(SUCCESS_THRESHOLD), n);
        int failureThreshold = resolveThreshold(FAILURE_THRESHOLD, ports().getInt(FAILURE_THRESHOLD).orElse(1), n);
        setStatus(NodeStatus.RUNNING);
        for (int i = 0; i < n; i++) {
            if (finished[i]) {
                continue;
            }
            NodeStatus childStatus = tickChild(i);
            if (childStatus == NodeStatus.SUCCESS) {
                finished[i] = true;
                successes++;
                if (successes >= successThreshold) {
                    return finish(NodeStatus.SUCCESS);
                }
            } else if (childStatus == NodeStatus.FAILURE) {
                finished[i] = true;
                failures++;
                if (failures >= failureThreshold || failures > n - successThreshold) {
                    return finish(NodeStatus.FAILURE);
                }
            }
        }
        return NodeStatus.RUNNING;
    }

    private NodeStatus finish(NodeStatus result) {
        reset();
        haltChildren();
        return result;
    }

    private void reset() {
        java.util.Arrays.fill(finished, false);
        successes = 0;
        failures = 0;
    }

    @Override
    protected void onHalt() {
        reset();
        super.onHalt();
    }
}
