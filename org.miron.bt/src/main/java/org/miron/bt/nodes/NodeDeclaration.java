package org.miron.bt.nodes;

import java.util.Map;

/**
 * A node declared in a {@code <TreeNodesModel>}: its ID, the element that declares it (Action,
 * Condition, Control, Decorator, SubTree) and its ports by name with their description.
 */
public record NodeDeclaration(String id, String kind, Map<String, Port> ports) {

    /** A port: input_port, output_port or inout_port, with the element's text as description. */
    public record Port(String name, String direction, String description) {
        /** Whether the node writes the port: output_port or inout_port. */
        public boolean writes() {
            return !direction.equals(PortDirection.INPUT.xmlName());
        }

        /** Whether the node reads the port: input_port or inout_port. */
        public boolean reads() {
            return !direction.equals(PortDirection.OUTPUT.xmlName());
        }
    }

    /** The names of the output_port ports (written by the node, never read). */
    public java.util.Set<String> outputPorts() {
        java.util.Set<String> outputs = new java.util.LinkedHashSet<>();
        ports.values().stream().filter(p -> !p.reads()).forEach(p -> outputs.add(p.name()));
        return outputs;
    }
}
