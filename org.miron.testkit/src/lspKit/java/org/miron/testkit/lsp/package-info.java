/**
 * The test kit's LSP part (configuration {@code lspKit}): a real LSP4J client of the MIRoN
 * language server, for org.miron.lsp's tests and those of {@code miron lsp}. Compiled against
 * org.miron.lsp, which its users already depend on.
 */
package org.miron.testkit.lsp;
