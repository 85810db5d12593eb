package org.miron.executor;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import org.miron.executor.skills.BlackboardFeed;
import org.miron.executor.skills.VariantSource;
import org.miron.executor.trace.StatusListener;

/**
 * A runnable behaviour tree: its root node, its root blackboard and its context. Ticks come from
 * one thread at a time; {@link #stop()} may be called from any thread.
 */
public final class Tree {
    private final String id;
    private final Node root;
    private final Blackboard blackboard;
    private final TreeContext context;
    private final int formatVersion;
    private final List<BlackboardFeed> feeds = new CopyOnWriteArrayList<>();
    /** A stop asked for and not yet honoured (see {@link #stop()}). */
    private final AtomicBoolean stopRequested = new AtomicBoolean();

    public Tree(String id, Node root, Blackboard blackboard, TreeContext context) {
        this(id, root, blackboard, context, 3);
    }

    /** @param formatVersion the BehaviorTree.CPP version whose semantics the nodes follow (3 or 4) */
    public Tree(String id, Node root, Blackboard blackboard, TreeContext context, int formatVersion) {
        this.formatVersion = formatVersion;
        this.id = id;
        this.root = root;
        this.blackboard = blackboard;
        this.context = context;
    }

    /**
     * Ticks the root once; a finished root is set back to IDLE so the next tick starts over (as
     * BT.CPP 3). In a version-4 tree this is BT.CPP 4's tickOnce: while the root is RUNNING and a
     * node asked for a wake-up, the root is ticked again at once (at most
     * {@link TreeContext#maxLoopsPerTick()} times, so Repeat(-1) over a child that succeeds at once
     * cannot hang the tree).
     */
    public NodeStatus tickRoot() {
        return tick(true);
    }

    /** BT.CPP 4's tickExactlyOnce: one tick of the root, wake-ups are not followed. */
    public NodeStatus tickExactlyOnce() {
        return tick(false);
    }

    private NodeStatus tick(boolean followWakeUps) {
        for (BlackboardFeed feed : feeds) {
            feed.applyTo(blackboard);
        }
        context.takeWakeUp();
        NodeStatus status = root.executeTick();
        for (int again = 0; followWakeUps && status == NodeStatus.RUNNING && again < context.maxLoopsPerTick()
                && context.takeWakeUp(); again++) {
            status = root.executeTick();
        }
        if (status.isCompleted()) {
            root.halt();
        }
        return status;
    }

    /**
     * Ticks the root every {@code period} while it returns RUNNING and returns its final status.
     * If {@link #stop()} is called or the thread is interrupted, halts the tree and returns RUNNING
     * (the interrupt flag is kept); a stop asked for before the call returns RUNNING at once.
     */
    public NodeStatus tickWhileRunning(Duration period) {
        if (stopRequested.getAndSet(false)) {
            return NodeStatus.RUNNING;
        }
        NodeStatus status = tickRoot();
        while (status == NodeStatus.RUNNING) {
            if (stopRequested.getAndSet(false) || !pause(period)) {
                haltTree();
                return NodeStatus.RUNNING;
            }
            status = tickRoot();
        }
        return status;
    }

    private static boolean pause(Duration period) {
        try {
            if (!period.isZero() && !period.isNegative()) {
                Thread.sleep(period.toMillis(), period.toNanosPart() % 1_000_000);
            }
            return !Thread.currentThread().isInterrupted();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /**
     * Makes the running {@link #tickWhileRunning} halt the tree and return, or the next one if none
     * runs: a stop that falls between two runs (a robot going round its missions) is not forgotten.
     * Honoured once; safe from any thread.
     */
    public void stop() {
        stopRequested.set(true);
    }

    /** Halts whatever runs and sets every node back to IDLE (call it on the ticking thread). */
    public void haltTree() {
        root.halt();
        for (Node node : nodes()) {
            node.halt();
        }
    }

    /** Copies numeric decisions from {@code source} into the root blackboard before every tick. */
    public void feedBlackboardFrom(VariantSource source) {
        feeds.add(new BlackboardFeed(source));
    }

    public String id() {
        return id;
    }

    /** The BehaviorTree.CPP version the tree runs as: its file's BTCPP_format (3 when absent). */
    public int formatVersion() {
        return formatVersion;
    }

    public Node root() {
        return root;
    }

    public Blackboard blackboard() {
        return blackboard;
    }

    public TreeContext context() {
        return context;
    }

    public void addListener(StatusListener listener) {
        context.addListener(listener);
    }

    /** Every node, depth first, root first. */
    public List<Node> nodes() {
        List<Node> all = new ArrayList<>();
        collect(root, all);
        return all;
    }

    private static void collect(Node node, List<Node> into) {
        into.add(node);
        for (Node child : node.children()) {
            collect(child, into);
        }
    }

    /** The tree as an indented outline with each node's status, for people (like BT.CPP's printTreeRecursively). */
    public String render() {
        StringBuilder text = new StringBuilder();
        render(root, 0, text);
        return text.toString();
    }

    private static void render(Node node, int depth, StringBuilder into) {
        into.append("  ".repeat(depth)).append(node.name()).append(" [").append(node.status()).append("]\n");
        for (Node child : node.children()) {
            render(child, depth + 1, into);
        }
    }

    /** The first node (depth first) whose path ends with {@code suffix}, e.g. "deliver/objectdrop". */
    public Optional<Node> find(String suffix) {
        for (Node node : nodes()) {
            if (node.path().equals(suffix) || node.path().endsWith("/" + suffix)) {
                return Optional.of(node);
            }
        }
        return Optional.empty();
    }
}
