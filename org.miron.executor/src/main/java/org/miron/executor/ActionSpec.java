package org.miron.executor;

/** What an action factory is given: the action ID, whether the XML said Action or Condition, and the node's info. */
public record ActionSpec(String id, Kind kind, NodeInfo info) {

    /** The element the node was written as. */
    public enum Kind {
        ACTION, CONDITION
    }

    public Ports ports() {
        return info.ports();
    }
}
