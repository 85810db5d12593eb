/**
 * The BehaviorTree.CPP 4 scripting language at run time: scripts parsed once by the BT language
 * ({@code BtScripts}) are compiled by {@link org.miron.executor.scripting.ScriptCompiler} into
 * {@link org.miron.executor.scripting.ScriptCode} closures over a
 * {@link org.miron.executor.scripting.ScriptScope} (blackboard and enums); {@code ScriptOperators}
 * and {@link org.miron.executor.scripting.ScriptValues} hold BT.CPP 4's value rules. Apart from the
 * nodes so that the value rules are tested and changed in one place.
 */
package org.miron.executor.scripting;
