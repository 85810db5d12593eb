package org.miron.executor.actions;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** SetBlackboard(value, output_key): writes value to the entry output_key names; SUCCESS. */
public class SetBlackboardNode extends Node {

    public SetBlackboardNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        if (!ports().has("output_key")) {
            throw ports().missing("output_key");
        }
        Object value = ports().get("value").orElseThrow(() -> ports().missing("value"));
        ports().set("output_key", value);
        return NodeStatus.SUCCESS;
    }
}
