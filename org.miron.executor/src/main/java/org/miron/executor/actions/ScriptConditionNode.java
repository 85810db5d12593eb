package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.CODE;

import java.util.Map;
import org.miron.executor.BtRuntimeException;
import org.miron.executor.Conditions;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.scripting.ScriptCode;
import org.miron.executor.scripting.ScriptException;
import org.miron.executor.scripting.ScriptValues;

/** ScriptCondition(code) (BT.CPP 4): SUCCESS when its script is true, FAILURE when false. */
public final class ScriptConditionNode extends Node {
    private final ScriptCode code;
    private final Map<String, Integer> enums;

    public ScriptConditionNode(NodeInfo info, ScriptCode code, Map<String, Integer> enums) {
        super(info);
        this.code = code;
        this.enums = enums;
    }

    @Override
    protected NodeStatus tick() {
        return isTrue(this, CODE, Conditions.runScript(code, this, CODE, enums)) ? NodeStatus.SUCCESS : NodeStatus.FAILURE;
    }

    /** A script's value as a condition, a value that is none being the node's error. */
    public static boolean isTrue(Node node, String attribute, Object value) {
        try {
            return ScriptValues.toBoolean(value);
        } catch (ScriptException e) {
            throw new BtRuntimeException(node.path() + ": " + attribute + ": " + e.getMessage(), e);
        }
    }
}
