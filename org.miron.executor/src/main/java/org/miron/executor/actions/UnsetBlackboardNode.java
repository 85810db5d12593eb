package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.KEY;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** UnsetBlackboard(key) (BT.CPP 4): removes the entry and succeeds. */
public final class UnsetBlackboardNode extends Node {
    public UnsetBlackboardNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        String key = ports().getString(KEY).orElseThrow(() -> ports().missing(KEY));
        ports().blackboard().set(key, null);
        return NodeStatus.SUCCESS;
    }
}
