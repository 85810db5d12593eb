/**
 * The built-in leaves that need nothing outside the tree: AlwaysSuccess/AlwaysFailure,
 * SetBlackboard/UnsetBlackboard, Sleep, the version-4 Script and ScriptCondition and the
 * entry-updated check (BehaviorTree.CPP's {@code actions/}). Leaves that call out of the tree (skills,
 * variants) are in {@code org.miron.executor.skills}; user actions are plugged in through
 * {@code ActionRegistry}.
 */
package org.miron.executor.actions;
