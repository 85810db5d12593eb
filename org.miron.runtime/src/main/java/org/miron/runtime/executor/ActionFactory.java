package org.miron.runtime.executor;

/** Makes the runtime node of one action or condition of the tree. */
@FunctionalInterface
public interface ActionFactory {
    Node create(ActionSpec spec);
}
