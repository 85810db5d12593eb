package org.miron.executor.actions;

import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/** AlwaysSuccess. */
public class AlwaysSuccessNode extends Node {

    public AlwaysSuccessNode(NodeInfo info) {
        super(info);
    }

    @Override
    protected NodeStatus tick() {
        return NodeStatus.SUCCESS;
    }
}
