package org.miron.runtime.executor;

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
