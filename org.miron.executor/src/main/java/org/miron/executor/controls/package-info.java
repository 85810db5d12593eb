/**
 * The built-in control nodes: Sequence, Fallback and their memory and reactive forms, Parallel,
 * IfThenElse, WhileDoElse and Switch. Where BehaviorTree.CPP 4 changed a node's behaviour the
 * version-4 class ({@code *V4}) sits beside the version-3 one; the tables of
 * {@code BuiltinFactories} (one per version) choose between them. Kept apart from the tree's core so that each
 * family of nodes is found in one place, as in BehaviorTree.CPP's {@code controls/}.
 */
package org.miron.executor.controls;
