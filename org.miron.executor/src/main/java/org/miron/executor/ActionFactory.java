package org.miron.executor;

/** Makes the runtime node of one action or condition of the tree. */
@FunctionalInterface
public interface ActionFactory {
    Node create(ActionSpec spec);
}
