package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.OUTPUT_KEY;
import static org.miron.bt.nodes.BuiltinNodes.VALUE;

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
        if (!ports().has(OUTPUT_KEY)) {
            throw ports().missing(OUTPUT_KEY);
        }
        Object value = ports().get(VALUE).orElseThrow(() -> ports().missing(VALUE));
        ports().set(OUTPUT_KEY, value);
        return NodeStatus.SUCCESS;
    }
}
