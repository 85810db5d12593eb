/**
 * The live monitor of {@code miron execute --monitor PORT} and {@code miron demo --monitor PORT}
 * (docs/diagrams.md): {@link org.miron.cli.monitor.LiveMonitor} draws the tree the executor runs
 * (org.miron.diagram's run-time view) and starts {@link org.miron.cli.monitor.MonitorServer}, the
 * JDK's HTTP server on 127.0.0.1 serving {@link org.miron.cli.monitor.MonitorPage} and server-sent
 * events; {@code MonitorState} keeps what the page shows from the bus (node statuses, varpoint
 * values, metrics, the decisions' explanations). With a Groot2 server to attach to
 * ({@code --groot}, {@code --monitor-groot}), {@code MonitorDebugger} is that server's Groot2 client
 * ({@link org.miron.runtime.groot.GrootConnection}) and {@code DebugRoutes} the page's requests to it;
 * {@code GrootTreeMap} places the server's uids on the page's node ids; {@code DebugPanel} is the
 * page's debugging section (docs/diagrams.md, "Debugging on the live page").
 *
 * <p>Why a Groot2 client and not the executor's hooks in the same process: one mechanism for
 * Groot2, the page and the tests, and the page debugs BehaviorTree.CPP's runner as it debugs ours.
 *
 * <p>{@code miron replay --monitor} serves the same page over a recording:
 * {@link org.miron.cli.monitor.ReplayMonitor} draws the recorded tree, {@link org.miron.cli.monitor.ReplayState}
 * tells a fresh MonitorState what was recorded up to an instant, {@link org.miron.cli.monitor.ReplayServer}
 * and {@link org.miron.cli.monitor.ReplayPage} add the time slider.
 *
 * <p>Why the bus and not the executor in the same process: the page then shows any executor that
 * publishes {@code miron.bt.status} (docs/wire-formats.md), goes on when one stops and another
 * starts, and an editor's diagram could follow the same messages. Why server-sent events: one
 * direction is all the page needs, browsers reconnect by themselves, and the JDK serves them
 * without a web framework.
 */
package org.miron.cli.monitor;
