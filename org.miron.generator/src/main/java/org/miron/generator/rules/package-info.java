/**
 * The design-time rule check (`miron check`, the language server): which rules can apply together
 * and cannot hold together, which never apply, which are always overridden, tried over sampled
 * situations with the engine's priority search (docs/issue-codes.md).
 */
package org.miron.generator.rules;
