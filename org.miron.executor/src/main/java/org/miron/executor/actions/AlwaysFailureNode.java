package org.miron.executor.actions;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** AlwaysFailure. */
public class AlwaysFailureNode extends Node {

    public AlwaysFailureNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        return NodeStatus.FAILURE;
    }
}
