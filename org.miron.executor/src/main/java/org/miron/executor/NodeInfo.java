package org.miron.executor;

/** What a node is told when it is built: its names, its ports and the tree it belongs to. */
public record NodeInfo(String name, String path, Ports ports, TreeContext context) {

    /** A node without a parent, for tests and hand-built trees. */
    public static NodeInfo of(String name, Ports ports, TreeContext context) {
        return new NodeInfo(name, name, ports, context);
    }
}
