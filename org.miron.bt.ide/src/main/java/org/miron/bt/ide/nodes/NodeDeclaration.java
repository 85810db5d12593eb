package org.miron.bt.ide.nodes;

import java.util.Map;

/**
 * A node declared in a {@code <TreeNodesModel>}: its ID, the element that declares it (Action,
 * Condition, Control, Decorator, SubTree) and its ports by name with their description.
 */
public record NodeDeclaration(String id, String kind, Map<String, Port> ports) {

    /** A port: input_port, output_port or inout_port, with the element's text as description. */
    public record Port(String name, String direction, String description) {
    }
}
