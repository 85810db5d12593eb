package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.CODE;

import java.util.Map;
import org.miron.executor.Conditions;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.scripting.ScriptCode;

/** Script(code) (BT.CPP 4): runs its script against the blackboard and succeeds. */
public final class ScriptNode extends Node {
    private final ScriptCode code;
    private final Map<String, Integer> enums;

    public ScriptNode(NodeInfo info, ScriptCode code, Map<String, Integer> enums) {
        super(info);
        this.code = code;
        this.enums = enums;
    }

    @Override
    protected NodeStatus tick() {
        Conditions.runScript(code, this, CODE, enums);
        return NodeStatus.SUCCESS;
    }
}
