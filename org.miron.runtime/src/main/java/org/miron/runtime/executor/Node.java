package org.miron.runtime.executor;

import java.util.List;

/**
 * A runtime node: BehaviorTree.CPP's TreeNode. The parent calls {@link #executeTick()}, which runs
 * the node's own {@link #tick()} and records the status it returns; {@link #halt()} stops it.
 * Nodes are ticked from one thread at a time (the tree's).
 */
public abstract class Node {
    private final NodeInfo info;
    private volatile NodeStatus status = NodeStatus.IDLE;

    protected Node(NodeInfo info) {
        this.info = info;
    }

    /** Ticks the node once and returns (and records) its new status, never IDLE. */
    public final NodeStatus executeTick() {
        NodeStatus result = tick();
        if (result == null || result == NodeStatus.IDLE) {
            throw new BtRuntimeException(path() + ": a node must never return " + result + " to its parent");
        }
        setStatus(result);
        return result;
    }

    /** The node's behaviour for one tick: RUNNING, SUCCESS or FAILURE. */
    protected abstract NodeStatus tick();

    /**
     * Stops the node and sets it back to IDLE. Only a RUNNING node is told to stop
     * ({@link #onHalt()}); one that has finished is just reset to IDLE, as BehaviorTree.CPP's
     * haltChild does, which is what lets a SequenceStar keep its position after a FAILURE.
     */
    public final void halt() {
        if (status == NodeStatus.RUNNING) {
            onHalt();
        }
        setStatus(NodeStatus.IDLE);
    }

    /** Stops whatever runs below or inside this node and forgets its progress. */
    protected void onHalt() {
    }

    protected final void setStatus(NodeStatus newStatus) {
        NodeStatus old = status;
        if (old != newStatus) {
            status = newStatus;
            info.context().fireStatusChanged(this, old, newStatus);
        }
    }

    public final NodeStatus status() {
        return status;
    }

    public List<Node> children() {
        return List.of();
    }

    /** The name shown in traces: the XML name attribute, else the action ID or the tag. */
    public final String name() {
        return info.name();
    }

    /** Names from the root down to this node, separated by '/'. */
    public final String path() {
        return info.path();
    }

    public final Ports ports() {
        return info.ports();
    }

    protected final TreeContext context() {
        return info.context();
    }

    @Override
    public String toString() {
        return path() + " [" + status + "]";
    }
}
