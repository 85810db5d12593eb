package org.miron.runtime.recording;

import java.util.List;
import org.miron.executor.NodeStatus;

/**
 * A FileLogger2 recording as read ({@link BtlogReader}): the tree XML of its header, when it started
 * (microseconds since the epoch), its transitions in order, and how many bytes of a last,
 * incomplete transition were left out (a recording cut short by a killed process).
 */
public record Recording(String treeXml, long startMicros, List<Transition> transitions, int trailingBytes) {
    /** One status change: microseconds since the start, the node's uid, its new status. */
    public record Transition(long micros, int uid, NodeStatus status) {
    }

    /** Microseconds from the start to the last transition (0 without any). */
    public long durationMicros() {
        return transitions.isEmpty() ? 0 : transitions.get(transitions.size() - 1).micros();
    }
}
