package org.miron.executor.controls;

import static org.miron.bt.nodes.BuiltinNodes.FAILURE_COUNT;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_COUNT;

import java.util.Arrays;
import java.util.List;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * Version-4 Parallel(success_count = -1, failure_count = 1) (BT.CPP 4's parallel_node): ticks the
 * children not finished yet, in order, and after each one checks whether the node is done:
 * SUCCESS once success_count children succeeded, FAILURE once failure_count failed or success can
 * no longer be reached; then it halts every child. A negative count counts from the number of
 * children (-1 = all); with a negative success_count, skipped children count as successes.
 * A count larger than the number of children is an error. All children skipped: SKIPPED.
 */
public final class ParallelNodeV4 extends ControlNode {
    private final boolean[] finished;
    private int successes;
    private int failures;

    public ParallelNodeV4(NodeInfo info, List<Node> children) {
        super(info, children);
        finished = new boolean[children.size()];
    }

    /** A count as written (maybe negative) resolved against the number of children, as BT.CPP 4. */
    public static int resolve(String port, int written, int childCount) {
        int count = written < 0 ? Math.max(childCount + written + 1, 0) : written;
        if (count > childCount) {
            throw new BtRuntimeException(port + "=" + written + " but there are only " + childCount + " children");
        }
        return count;
    }

    @Override
    protected NodeStatus tick() {
        int n = children.size();
        int writtenSuccess = ports().getInt(SUCCESS_COUNT).orElse(-1);
        int required;
        int failureCount;
        try {
            required = resolve(SUCCESS_COUNT, writtenSuccess, n);
            failureCount = resolve(FAILURE_COUNT, ports().getInt(FAILURE_COUNT).orElse(1), n);
        } catch (BtRuntimeException e) {
            throw new BtRuntimeException(path() + ": " + e.getMessage(), e);
        }
        setStatus(NodeStatus.RUNNING);
        int skipped = 0;
        for (int i = 0; i < n; i++) {
            if (!finished[i]) {
                NodeStatus childStatus = tickChild(i);
                if (childStatus == NodeStatus.SKIPPED) {
                    skipped++;
                } else if (childStatus == NodeStatus.SUCCESS) {
                    finished[i] = true;
                    successes++;
                } else if (childStatus == NodeStatus.FAILURE) {
                    finished[i] = true;
                    failures++;
                }
            }
            if (successes >= required || (writtenSuccess < 0 && successes + skipped >= required)) {
                return finish(NodeStatus.SUCCESS);
            }
            if (n - failures < required || failures == failureCount) {
                return finish(NodeStatus.FAILURE);
            }
        }
        return skipped == n ? NodeStatus.SKIPPED : NodeStatus.RUNNING;
    }

    private NodeStatus finish(NodeStatus result) {
        reset();
        haltChildren();
        return result;
    }

    private void reset() {
        Arrays.fill(finished, false);
        successes = 0;
        failures = 0;
    }

    @Override
    protected void onHalt() {
        reset();
        super.onHalt();
    }
}
