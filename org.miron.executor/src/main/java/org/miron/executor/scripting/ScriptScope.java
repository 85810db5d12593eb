package org.miron.executor.scripting;

import java.util.Map;
import org.miron.executor.Blackboard;

/** What a script sees: the blackboard of the node it belongs to and the registered enum names. */
public record ScriptScope(Blackboard blackboard, Map<String, Integer> enums) {
}
