/**
 * The built-in decorators: Inverter, Force*, Repeat/Retry (and their version-4 form), Timeout,
 * Delay, KeepRunningUntilFailure, BlackboardCheck, the version-4 Precondition, RunOnce, Loop*
 * and entry-updated decorators, and SubTree (a decorator over the expanded subtree, as in
 * BehaviorTree.CPP's {@code decorators/}). Nodes that wait read the tree's clock at tick time
 * through {@code RunTimer}, so runs are deterministic under a fake clock.
 */
package org.miron.executor.decorators;
