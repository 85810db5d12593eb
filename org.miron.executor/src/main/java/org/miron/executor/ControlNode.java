package org.miron.executor;

import java.util.List;

/** A node with one or more children. */
public abstract class ControlNode extends Node {
    protected final List<Node> children;

    protected ControlNode(NodeInfo info, List<Node> children) {
        super(info);
        if (children.isEmpty()) {
            throw new BtBuildException(info.path() + ": a control node needs at least one child");
        }
        this.children = List.copyOf(children);
    }

    @Override
    public List<Node> children() {
        return children;
    }

    protected final void haltChild(int index) {
        children.get(index).halt();
    }

    protected final void haltChildren() {
        haltChildrenFrom(0);
    }

    protected final void haltChildrenFrom(int first) {
        for (int i = first; i < children.size(); i++) {
            children.get(i).halt();
        }
    }

    /** Subclasses reset their progress here, then call super to halt the children. */
    @Override
    protected void onHalt() {
        haltChildren();
    }

    protected final NodeStatus tickChild(int index) {
        return children.get(index).executeTick();
    }
}
