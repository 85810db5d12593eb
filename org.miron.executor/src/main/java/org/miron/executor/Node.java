package org.miron.executor;

import java.util.List;
import org.miron.bt.nodes.NodeKind;

/**
 * A runtime node: BehaviorTree.CPP's TreeNode. The parent calls {@link #executeTick()}, which runs
 * the node's own {@link #tick()} and records the status it returns; {@link #halt()} stops it.
 * Nodes are ticked from one thread at a time (the tree's).
 */
public abstract class Node {
    private final NodeInfo info;
    private volatile NodeStatus status = NodeStatus.IDLE;
    /** Version-4 pre/post-conditions; null in a version-3 tree, which has none. */
    private Conditions conditions;
    /** The registration name and kind BehaviorTree.CPP would give it (the builder sets them; monitors read them). */
    private String element;
    private NodeKind kind;

    protected Node(NodeInfo info) {
        this.info = info;
    }

    /**
     * Ticks the node once and returns (and records) its new status, never IDLE. In a version-4
     * tree the pre-conditions may decide the status instead of {@link #tick()}, the post-conditions
     * run when it has finished, and a SKIPPED node stays IDLE (as BT.CPP 4's executeTick).
     */
    public final NodeStatus executeTick() {
        NodeStatus result = conditions == null ? null : conditions.before(this);
        if (result == null && !status.isCompleted()) {
            // as BT.CPP's pre-tick callback: asked only when no pre-condition decided and the node has not finished
            result = info.context().beforeTick(this);
        }
        if (result == null) {
            result = tick();
        }
        if (result == null || result == NodeStatus.IDLE) {
            throw new BtRuntimeException(path() + ": a node must never return " + result + " to its parent");
        }
        if (conditions != null) {
            if (result.isCompleted()) {
                conditions.after(this, result);
            }
            afterTickV4();
        }
        if (result != NodeStatus.SKIPPED) {
            setStatus(result);
        }
        return result;
    }

    /** Version 4 only: what BT.CPP 4 does after every tick of this kind of node (decorators reset a finished child). */
    void afterTickV4() {
    }

    /** Makes this a version-4 node with these pre/post-conditions (the builder calls it once). */
    final void useConditions(Conditions conditions) {
        this.conditions = conditions;
    }

    /** Records what the node was built from (the builder calls it once). */
    final void useElement(String element, NodeKind kind) {
        this.element = element;
        this.kind = kind;
    }

    /**
     * The name BehaviorTree.CPP registers this node under: the tag of a built-in ({@code Sequence}),
     * the ID of an action or user node ({@code Pick}), {@code SubTree} for a subtree call; its name
     * when built by hand.
     */
    public final String element() {
        return element != null ? element : name();
    }

    /** The node's kind as in a TreeNodesModel; ACTION when built by hand and not a control or decorator. */
    public final NodeKind kind() {
        if (kind != null) {
            return kind;
        }
        return this instanceof ControlNode ? NodeKind.CONTROL : this instanceof DecoratorNode ? NodeKind.DECORATOR : NodeKind.ACTION;
    }

    /** True in a version-4 tree (BTCPP_format="4"). */
    protected final boolean isVersion4() {
        return conditions != null;
    }

    /** The node's behaviour for one tick: RUNNING, SUCCESS or FAILURE (or, in version 4, SKIPPED). */
    protected abstract NodeStatus tick();

    /**
     * Stops the node and sets it back to IDLE. Only a RUNNING node is told to stop
     * ({@link #onHalt()}); one that has finished is just reset to IDLE, as BehaviorTree.CPP's
     * haltChild does, which is what lets a SequenceStar keep its position after a FAILURE.
     */
    public final void halt() {
        boolean running = status == NodeStatus.RUNNING;
        if (running) {
            onHalt();
        }
        setStatus(NodeStatus.IDLE);
        if (running && conditions != null) {
            conditions.halted(this);
        }
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
