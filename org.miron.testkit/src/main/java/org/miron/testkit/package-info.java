/**
 * What the modules' tests share, and the only way they share test code (docs/testing.md): the
 * repository root, copies of the examples, the JSON Schemas of docs/, and the real
 * BehaviorTree.CPP 4 (its python and the loading oracle). It brings JUnit only, so every module's
 * tests may have it.
 */
package org.miron.testkit;
