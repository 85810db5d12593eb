package org.miron.executor.scripting;

/**
 * A script of BehaviorTree.CPP 4's scripting language, parsed once when the tree is built and run
 * on every tick that needs it. Its value is that of its last statement: a Long, a Double or a
 * String (booleans are the integers 1 and 0, as in BT.CPP).
 */
@FunctionalInterface
public interface ScriptCode {
    /** Runs the script; a script that cannot run (unknown key, mixed types) throws ScriptException. */
    Object run(ScriptScope scope);
}
