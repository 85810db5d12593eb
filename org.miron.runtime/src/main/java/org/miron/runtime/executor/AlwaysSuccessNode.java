package org.miron.runtime.executor;

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
