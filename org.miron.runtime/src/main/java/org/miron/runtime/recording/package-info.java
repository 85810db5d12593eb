/**
 * Recordings of a run, in BehaviorTree.CPP 4's FileLogger2 format (what Groot2 opens, and what the
 * C++ runner writes with the library's own logger): the layout ({@link org.miron.runtime.recording.Btlog}),
 * the writer for a tree of the Java executor ({@link org.miron.runtime.recording.BtlogWriter}, its
 * header the tree as org.miron.runtime.groot numbers and writes it), the reader of either's files
 * ({@link org.miron.runtime.recording.BtlogReader} into a {@link org.miron.runtime.recording.Recording}),
 * the header's tree put together again with each node's live-page id
 * ({@link org.miron.runtime.recording.RecordedTree}); and the run's bus beside it as JSON Lines
 * ({@link org.miron.runtime.recording.BusLog}, {@link org.miron.runtime.recording.BusLogReader}).
 * Why the library's format and not our own: Groot2 and BT.CPP users' tools open it, and a C++ run
 * and a Java run of the same tree can be compared file to file (RecordingOracleTest). What differs
 * from the library: docs/bt-semantics.md, "Recordings".
 */
package org.miron.runtime.recording;
