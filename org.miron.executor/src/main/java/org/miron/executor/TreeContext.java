package org.miron.executor;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.miron.executor.trace.StatusListener;
import org.miron.executor.trace.TickHook;

/** What every node of one tree shares: the clock, the status listeners and the loop guard. */
public final class TreeContext {
    /**
     * Default bound on the child re-ticks a Repeat or Retry may do within one tick. BehaviorTree.CPP
     * loops without bound, so Repeat(-1) over a child that succeeds at once never returns; past this
     * bound we return RUNNING instead (keeping the count), and the next tick carries on.
     */
    public static final int DEFAULT_MAX_LOOPS_PER_TICK = 1000;

    private final MillisClock clock;
    private final int maxLoopsPerTick;
    private final List<StatusListener> listeners = new CopyOnWriteArrayList<>();
    /** The listeners as an array, replaced on change: a status change iterates without allocating (the simulator's coverage listens to every one). */
    private volatile StatusListener[] listening = new StatusListener[0];
    private volatile boolean wakeUp;
    private volatile Consumer<String> problems = System.err::println;
    private volatile TickHook tickHook;

    public TreeContext() {
        this(MillisClock.SYSTEM, DEFAULT_MAX_LOOPS_PER_TICK);
    }

    public TreeContext(MillisClock clock) {
        this(clock, DEFAULT_MAX_LOOPS_PER_TICK);
    }

    public TreeContext(MillisClock clock, int maxLoopsPerTick) {
        if (maxLoopsPerTick < 1) {
            throw new IllegalArgumentException("maxLoopsPerTick must be at least 1");
        }
        this.clock = clock;
        this.maxLoopsPerTick = maxLoopsPerTick;
    }

    public MillisClock clock() {
        return clock;
    }

    public int maxLoopsPerTick() {
        return maxLoopsPerTick;
    }

    /**
     * A version-4 node asks for the tree to be ticked again at once (BT.CPP 4's emitWakeUpSignal:
     * SequenceWithMemory, Repeat and RetryUntilSuccessful yield after each child that finished
     * within one tick, and {@link Tree#tickRoot()} ticks again).
     */
    public void emitWakeUp() {
        wakeUp = true;
    }

    /** Whether a wake-up was asked for since the last call, and forgets it. */
    boolean takeWakeUp() {
        boolean asked = wakeUp;
        wakeUp = false;
        return asked;
    }

    /**
     * Where a node's one-line account of why it failed goes (a skill not pushed because an input
     * key has no value...): standard error unless set, e.g. to a test's list or a log.
     */
    public void onProblem(Consumer<String> sink) {
        problems = sink;
    }

    /** Reports one line through {@link #onProblem}. */
    public void reportProblem(String line) {
        problems.accept(line);
    }

    /** Sets (null: removes) the hook asked before each node's tick; one at a time. */
    public void setTickHook(TickHook hook) {
        tickHook = hook;
    }

    /** The hook's decision for this node (null: tick it), or null without a hook. */
    NodeStatus beforeTick(Node node) {
        TickHook hook = tickHook;
        if (hook == null) {
            return null;
        }
        NodeStatus decided = hook.beforeTick(node);
        return decided != null && decided.isCompleted() ? decided : null;
    }

    public synchronized void addListener(StatusListener listener) {
        listeners.add(listener);
        listening = listeners.toArray(new StatusListener[0]);
    }

    public synchronized void removeListener(StatusListener listener) {
        listeners.remove(listener);
        listening = listeners.toArray(new StatusListener[0]);
    }

    void fireStatusChanged(Node node, NodeStatus from, NodeStatus to) {
        StatusListener[] all = listening;
        if (all.length == 0) {
            return;
        }
        long now = clock.nowMillis();
        for (StatusListener listener : all) {
            try {
                listener.statusChanged(now, node, from, to);
            } catch (RuntimeException e) {
                // a broken monitor must not stop the robot's behaviour; say so and carry on
                System.err.println("status listener " + listener + " failed on " + node.path() + ": " + e);
            }
        }
    }
}
