package org.miron.executor;

import java.util.List;

/** A node with exactly one child. */
public abstract class DecoratorNode extends Node {
    protected final Node child;

    protected DecoratorNode(NodeInfo info, Node child) {
        super(info);
        if (child == null) {
            throw new BtBuildException(info.path() + ": a decorator needs exactly one child");
        }
        this.child = child;
    }

    @Override
    public List<Node> children() {
        return List.of(child);
    }

    /** Halts a running child, or sets a finished one back to IDLE. */
    protected final void resetChild() {
        child.halt();
    }

    @Override
    protected void onHalt() {
        resetChild();
    }

    /** BT.CPP 4's DecoratorNode::executeTick: a child left finished is set back to IDLE. */
    @Override
    void afterTickV4() {
        if (child.status().isCompleted()) {
            child.halt();
        }
    }
}
