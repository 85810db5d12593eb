package org.miron.executor.trace;

import java.io.PrintStream;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;

/**
 * Prints each status change as one line, when it happens:
 * {@code 08:01:02.345  Main/PickDeliverChargeSubtree/deliver/objectdrop  IDLE -> RUNNING}.
 * A halt (RUNNING → IDLE) is always shown and marked; the resets of finished nodes to IDLE, which
 * follow every completion, can be left out.
 */
public final class ConsoleTracePrinter implements StatusListener {
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private final PrintStream out;
    private final ZoneId zone;
    private final boolean showResets;

    /** To standard output, local time, resets of finished nodes included. */
    public ConsoleTracePrinter() {
        this(System.out, ZoneId.systemDefault(), true);
    }

    /** @param showResets whether to print the SUCCESS/FAILURE → IDLE lines of finished nodes being reset */
    public ConsoleTracePrinter(PrintStream out, ZoneId zone, boolean showResets) {
        this.out = out;
        this.zone = zone;
        this.showResets = showResets;
    }

    @Override
    public void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        if (to == NodeStatus.IDLE && from.isCompleted() && !showResets) {
            return;
        }
        out.println(format(timeMillis, node, from, to));
        out.flush();
    }

    public String format(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        return TIME.format(Instant.ofEpochMilli(timeMillis).atZone(zone)) + "  " + node.path() + "  " + from + " -> " + to
                + (from == NodeStatus.RUNNING && to == NodeStatus.IDLE ? "  (halted)" : "");
    }
}
