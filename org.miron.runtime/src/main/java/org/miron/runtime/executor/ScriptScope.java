package org.miron.runtime.executor;

import java.util.Map;

/** What a script sees: the blackboard of the node it belongs to and the registered enum names. */
public record ScriptScope(Blackboard blackboard, Map<String, Integer> enums) {
}
