/**
 * Watching a running tree: {@link org.miron.executor.trace.StatusListener} is told of every status
 * change on the ticking thread; {@link org.miron.executor.trace.ConsoleTracePrinter} prints them one
 * line each as they happen (BehaviorTree.CPP keeps its loggers apart the same way). Observers such as
 * the demo's narrator or {@code miron execute} depend on the listener, not on the nodes.
 */
package org.miron.executor.trace;
