package org.miron.executor;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.miron.executor.trace.StatusListener;

/** Records status changes as "path FROM->TO" lines. */
final class TraceRecorder implements StatusListener {
    final List<String> lines = new ArrayList<>();

    @Override
    public void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        lines.add(node.path() + " " + from + "->" + to);
    }

    /** The lines about nodes whose path ends with {@code suffix}. */
    List<String> of(String suffix) {
        return lines.stream().filter(l -> l.substring(0, l.lastIndexOf(' ')).endsWith(suffix)).collect(Collectors.toList());
    }
}
