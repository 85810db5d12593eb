package org.miron.executor.controls;

import static org.miron.bt.nodes.BuiltinNodes.CASE_PREFIX;
import static org.miron.bt.nodes.BuiltinNodes.VARIABLE;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.miron.executor.BtBuildException;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * SwitchN(variable, case_1..case_N): N+1 children, the last being the default. Ticks the child of
 * the first case equal to the variable's value (the default when the variable is missing or no
 * case matches); when the choice changes while a child runs, that child is halted first.
 */
public class SwitchNode extends ControlNode {
    private final int cases;
    /** Version 4 also matches equal numbers and enum names ("2" and "2.0", "RED" and "1"); null in version 3. */
    private final Map<String, Integer> v4Enums;
    private int runningChild = -1;

    public SwitchNode(NodeInfo info, int cases, List<Node> children) {
        this(info, cases, children, null);
    }

    /** @param v4Enums the scripting enums for a version-4 tree, null for version 3 */
    public SwitchNode(NodeInfo info, int cases, List<Node> children, Map<String, Integer> v4Enums) {
        super(info, children);
        this.v4Enums = v4Enums;
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
        // no RUNNING before the child's tick, unlike Sequence: BT.CPP's Switch (3 and 4) sets none, so
        // a recording shows the Switch RUNNING only after its running child (RecordingOracleTest)
        NodeStatus result = tickChild(match);
        if (result == NodeStatus.SKIPPED) {
            runningChild = -1;
            return result;
        }
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
        Optional<String> variable = ports().getString(VARIABLE);
        if (variable.isPresent()) {
            for (int i = 0; i < cases; i++) {
                Optional<String> value = ports().getString(CASE_PREFIX + (i + 1));
                if (value.isPresent() && matches(variable.get(), value.get())) {
                    return i;
                }
            }
        }
        return cases;
    }

    private boolean matches(String variable, String value) {
        if (variable.equals(value)) {
            return true;
        }
        if (v4Enums == null) {
            return false;
        }
        // BT.CPP 4's CheckStringEquality: as integers (enum names included), then as reals
        Long a = asInteger(variable);
        Long b = asInteger(value);
        if (a != null && b != null && a.equals(b)) {
            return true;
        }
        try {
            return Math.abs(Double.parseDouble(variable.trim()) - Double.parseDouble(value.trim())) <= Math.ulp(1.0f);
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private Long asInteger(String text) {
        Integer named = v4Enums.get(text);
        if (named != null) {
            return named.longValue();
        }
        try {
            return Long.parseLong(text.trim());
        } catch (NumberFormatException e) {
            return null;
        }
    }

    @Override
    protected void onHalt() {
        runningChild = -1;
        super.onHalt();
    }
}
