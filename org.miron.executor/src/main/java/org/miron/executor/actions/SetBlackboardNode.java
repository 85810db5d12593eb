package org.miron.executor.actions;

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
        if (!ports().has("output_key")) {
            throw ports().missing("output_key");
        }
        Optional<Object> value = ports().get("value");
        if (value.isEmpty()) {
            Optional<String> key = Ports.blackboardKey("value", ports().raw("value"));
            if (isVersion4() && key.isPresent() && ports().blackboard().contains(key.get())) {
                context().reportProblem(ports().missingMessage("value"));
                return NodeStatus.FAILURE;
            }
            throw ports().missing("value");
        }
        ports().set("output_key", value.get());
        return NodeStatus.SUCCESS;
    }
}
