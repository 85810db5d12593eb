package org.miron.executor;

import java.util.List;

/** Makes the runtime node of a user-registered control node, given its already built children. */
@FunctionalInterface
public interface ControlFactory {
    Node create(NodeInfo info, List<Node> children);
}
