package org.miron.executor;

import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;

/**
 * An {@link AsyncAction} whose work is a future started on the first tick: RUNNING until the
 * future completes, then its SUCCESS or FAILURE (FAILURE also when it completes exceptionally);
 * halting cancels it. Lets Java actions run on their own threads without blocking the ticks.
 */
public final class FutureAction implements AsyncAction {
    private final Function<Ports, CompletableFuture<NodeStatus>> start;
    private CompletableFuture<NodeStatus> running;

    public FutureAction(Function<Ports, CompletableFuture<NodeStatus>> start) {
        this.start = Objects.requireNonNull(start);
    }

    @Override
    public NodeStatus onStart(Ports ports) {
        running = start.apply(ports);
        return onRunning(ports);
    }

    @Override
    public NodeStatus onRunning(Ports ports) {
        if (!running.isDone()) {
            return NodeStatus.RUNNING;
        }
        NodeStatus result = running.isCompletedExceptionally() ? NodeStatus.FAILURE : running.join();
        running = null;
        if (result != NodeStatus.SUCCESS && result != NodeStatus.FAILURE) {
            throw new BtRuntimeException("a future action must complete with SUCCESS or FAILURE, not " + result);
        }
        return result;
    }

    @Override
    public void onHalted() {
        if (running != null) {
            running.cancel(true);
            running = null;
        }
    }
}
