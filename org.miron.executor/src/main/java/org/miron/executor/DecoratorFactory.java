package org.miron.executor;

/** Makes the runtime node of a user-registered decorator, given its already built child. */
@FunctionalInterface
public interface DecoratorFactory {
    Node create(NodeInfo info, Node child);
}
