/**
 * What the modules' tests share, and the only way they share test code (docs/testing.md): the
 * repository root, copies of the examples, and the real BehaviorTree.CPP 4 (its python and the
 * loading oracle). JUnit is its only dependency, so every module's tests may have it.
 */
package org.miron.testkit;
