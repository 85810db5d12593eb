package org.miron.executor;

import java.util.Set;

/**
 * What an action factory is given: the action ID, whether the XML said Action or Condition, the
 * node's info and the ports the file's {@code <TreeNodesModel>} declares as output_port for this
 * ID (empty when undeclared): a skill does not send those, it writes them.
 */
public record ActionSpec(String id, Kind kind, NodeInfo info, Set<String> outputPorts) {

    /** The element the node was written as. */
    public enum Kind {
        ACTION, CONDITION
    }

    public ActionSpec {
        outputPorts = Set.copyOf(outputPorts);
    }

    /** An action whose ports no TreeNodesModel declares. */
    public ActionSpec(String id, Kind kind, NodeInfo info) {
        this(id, kind, info, Set.of());
    }

    public Ports ports() {
        return info.ports();
    }
}
