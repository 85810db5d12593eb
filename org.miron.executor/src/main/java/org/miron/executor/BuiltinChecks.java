package org.miron.executor;

import org.miron.bt.nodes.Children;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortDirection;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.nodes.PortType;

/**
 * The load-time checks the catalogue states for a built-in: how many children it takes, which
 * ports it needs, and that a literal (not a {@code {key}} pointer) converts to its port's type.
 * BehaviorTree.CPP finds most of these when the node first reads the port; finding them before
 * anything runs is the executor's rule (TreeBuilder: "reported here, before anything runs").
 */
final class BuiltinChecks {
    private BuiltinChecks() {
    }

    static void check(NodeModel node, int version, NodeInfo info, int childCount) {
        checkChildren(node, info, childCount);
        for (PortModel port : node.ports(version)) {
            String raw = info.ports().raw(port.name());
            if (raw == null) {
                if (port.required()) {
                    throw new BtBuildException(info.path() + ": missing parameter " + port.name());
                }
            } else if (port.direction() != PortDirection.OUTPUT && Ports.blackboardKey(port.name(), raw).isEmpty()
                    && !port.accepts(raw)) {
                throw new BtBuildException(info.path() + ": " + port.name() + ": not " + expected(port) + ": '"
                        + raw + "'");
            }
        }
    }

    static void checkChildren(NodeModel node, NodeInfo info, int count) {
        Children children = node.children();
        if (children.admits(count)) {
            return;
        }
        String tag = node.tag();
        if (node.kind() == NodeKind.DECORATOR) {
            throw new BtBuildException(info.path() + ": a decorator has exactly one child, " + tag + " has " + count);
        }
        if (children.equals(Children.AT_LEAST_ONE)) {
            throw new BtBuildException(info.path() + ": " + tag + " needs at least one child");
        }
        if (children.max() == 0) {
            throw new BtBuildException(info.path() + ": " + tag + " takes no children, has " + count);
        }
        throw new BtBuildException(info.path() + ": " + tag + " takes " + children.describe() + " children, has "
                + count);
    }

    /** What a literal of the port must be, e.g. "an integer of at least -1", "one of SUCCESS, FAILURE". */
    private static String expected(PortModel port) {
        if (!port.values().isEmpty()) {
            return "one of " + String.join(", ", port.values());
        }
        PortType type = port.type();
        if (type == PortType.INT && port.minimum() > Integer.MIN_VALUE) {
            return "an integer of at least " + port.minimum();
        }
        switch (type) {
        case INT:
            return "an integer";
        case UNSIGNED:
            return "a non-negative integer";
        case DOUBLE:
            return "a number";
        case BOOL:
            return "a boolean (" + String.join("/", PortType.BOOLEANS.stream().sorted().toList()) + ")";
        case STATUS:
            return "a node status";
        default:
            return "a " + type.cppName();
        }
    }
}
