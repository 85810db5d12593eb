package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.OUTPUT_KEY;
import static org.miron.bt.nodes.BuiltinNodes.VALUE;

import java.util.Optional;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;

/**
 * SetBlackboard(value, output_key): writes value to the entry output_key names; SUCCESS. A value
 * pointing at a key without a value is an error in version 3 (BT.CPP 3's getInput fails, the node
 * throws); in version 4 an entry that exists without a value makes the node fail (FAILURE, one
 * line reported), and only a key with no entry at all is an error, as BT.CPP 4.8 does.
 */
public class SetBlackboardNode extends Node {
    public SetBlackboardNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        if (!ports().has(OUTPUT_KEY)) {
            throw ports().missing(OUTPUT_KEY);
        }
        Optional<Object> value = ports().get(VALUE);
        if (value.isEmpty()) {
            Optional<String> key = Ports.blackboardKey(VALUE, ports().raw(VALUE));
            if (isVersion4() && key.isPresent() && ports().blackboard().contains(key.get())) {
                context().reportProblem(ports().missingMessage(VALUE));
                return NodeStatus.FAILURE;
            }
            throw ports().missing(VALUE);
        }
        ports().set(OUTPUT_KEY, value.get());
        return NodeStatus.SUCCESS;
    }
}
