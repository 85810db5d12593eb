package org.miron.executor.decorators;

import static org.miron.bt.nodes.BuiltinNodes.ELSE;
import static org.miron.bt.nodes.BuiltinNodes.IF;

import java.util.Map;
import org.miron.executor.Conditions;
import org.miron.executor.Conversions;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.actions.ScriptConditionNode;
import org.miron.executor.scripting.ScriptCode;

/**
 * Precondition(if, else = FAILURE) (BT.CPP 4): when the script {@code if} is true the child is
 * ticked, and then keeps being ticked without checking again until it finishes; when false, the
 * node returns {@code else} (SUCCESS, FAILURE, RUNNING or SKIPPED) without ticking it.
 */
public final class PreconditionNode extends DecoratorNode {
    private final ScriptCode condition;
    private final Map<String, Integer> enums;
    private boolean childRunning;

    public PreconditionNode(NodeInfo info, Node child, ScriptCode condition, Map<String, Integer> enums) {
        super(info, child);
        this.condition = condition;
        this.enums = enums;
    }

    @Override
    protected NodeStatus tick() {
        NodeStatus otherwise = ports().get(ELSE).map(Conversions::toStatusOrSkipped).orElse(NodeStatus.FAILURE);
        if (!childRunning) {
            childRunning = ScriptConditionNode.isTrue(this, IF, Conditions.runScript(condition, this, IF, enums));
        }
        if (!childRunning) {
            return otherwise;
        }
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
            childRunning = false;
        }
        return childStatus;
    }
}
