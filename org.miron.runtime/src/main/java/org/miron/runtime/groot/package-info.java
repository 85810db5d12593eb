/**
 * Groot2's protocol, served for a tree running in the Java executor as BehaviorTree.CPP 4's
 * Groot2Publisher serves it (a REP server on a port, a PUB on the next): the message headers
 * ({@link GrootProtocol}), the uid numbering and the tree as XML ({@link GrootTree},
 * {@link GrootTreeXml}), the status snapshot and recorded transitions ({@link StatusSnapshot}), the
 * subtrees' blackboards ({@link BlackboardDump}, {@link MsgPack}), breakpoints and replacements
 * ({@link GrootHooks}) and the sockets ({@link GrootServer}); and the client side,
 * {@link GrootConnection}, with which the live page debugs a tree through any such server, ours or
 * BT.CPP's. What differs from the library and why: docs/bt-semantics.md, "Groot2".
 */
package org.miron.runtime.groot;
