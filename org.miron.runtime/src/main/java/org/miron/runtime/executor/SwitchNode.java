package org.miron.runtime.executor;

import java.util.List;
import java.util.Optional;

/**
 * SwitchN(variable, case_1..case_N): N+1 children, the last being the default. Ticks the child of
 * the first case equal to the variable's value (the default when the variable is missing or no
 * case matches); when the choice changes while a child runs, that child is halted first.
 */
public class SwitchNode extends ControlNode {
    private final int cases;
    private int runningChild = -1;

    public SwitchNode(NodeInfo info, int cases, List<Node> children) {
        super(info, children);
        if (children.size() != cases + 1) {
            throw new BtBuildException(info.path() + ": Switch" + cases + " needs " + (cases + 1)
                    + " children (" + cases + " cases and a default), not " + children.size());
        }
        this.cases = cases;
    }

    @Override
    protected NodeStatus tick() {
        int match = selectedChild();
        if (runningChild != -1 && runningChild != match) {
            haltChild(runningChild);
        }
        setStatus(NodeStatus.RUNNING);
        NodeStatus result = tickChild(match);
        if (result == NodeStatus.RUNNING) {
            runningChild = match;
        } else {
            haltChildren();
            runningChild = -1;
        }
        return result;
    }

    /** Index of the child the variable selects now. */
    public int selectedChild() {
        Optional<String> variable = ports().getString("variable");
        if (variable.isPresent()) {
            for (int i = 0; i < cases; i++) {
                Optional<String> value = ports().getString("case_" + (i + 1));
                if (value.isPresent() && value.get().equals(variable.get())) {
                    return i;
                }
            }
        }
        return cases;
    }

    @Override
    protected void onHalt() {
        runningChild = -1;
        super.onHalt();
    }
}
