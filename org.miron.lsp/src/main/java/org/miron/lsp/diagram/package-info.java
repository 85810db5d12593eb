/**
 * The diagram server inside the language server: the protocol sprotty-vscode speaks with a Sprotty
 * server over LSP ({@code diagram/accept} carrying {@code {clientId, action}} both ways,
 * {@code diagram/didClose}, and {@code diagram/openInTextEditor} to reveal a node's source).
 *
 * <p>Why not {@code org.eclipse.sprotty.xtext}: its 1.1.1 release (the newest on Maven Central)
 * pins Xtext 2.33 and LSP4J 0.22, and ours are 2.42 and 0.24. The same protocol is built here on
 * Sprotty's own server classes ({@code DefaultDiagramServer} per diagram client, its JSON adapters)
 * and on {@code org.miron.diagram}'s models, so the editor shows what {@code miron render}, the demo
 * report and the live page show.
 *
 * <p>{@link org.miron.lsp.diagram.DiagramServers} keeps one {@link org.miron.lsp.diagram.MironDiagramServer}
 * per webview; after every document change it asks each for a new model, read from the workspace
 * by {@link org.miron.lsp.diagram.DiagramGeneration} in a read request queued after the change.
 */
package org.miron.lsp.diagram;
