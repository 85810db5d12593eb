/**
 * Language-server services of all three languages that stay quiet on half-written text: formatting
 * leaves files with syntax errors alone, navigation skips references that resolve to nothing and tokens that belong to no element, rename refuses with its own LSP error.
 * Bound for all three by {@link org.miron.bt.ide.server.MironServerBindings}.
 */
package org.miron.bt.ide.server;
