package org.miron.runtime.executor;

/** UnsetBlackboard(key) (BT.CPP 4): removes the entry and succeeds. */
public final class UnsetBlackboardNode extends Node {

    public UnsetBlackboardNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        String key = ports().getString("key").orElseThrow(() -> ports().missing("key"));
        ports().blackboard().set(key, null);
        return NodeStatus.SUCCESS;
    }
}
