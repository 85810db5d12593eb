/**
 * The catalogue of built-in behaviour-tree nodes: one {@link org.miron.bt.nodes.NodeModel} per
 * element the BT grammar parses as a built-in (tag and other spellings, kind, the BehaviorTree.CPP
 * versions that register it, what the other version writes instead, ports with direction, type,
 * default and description, how many children it takes). BehaviorTree.CPP's manifests are the
 * model: providedPorts() per node, and {@link org.miron.bt.nodes.NodeCatalogue#treeNodesModel}
 * writes the table in its {@code <TreeNodesModel>} format.
 *
 * <p>Readers: the validators (required and typed ports, child counts, version checks through
 * BtVersions), the IDE (completion per version, hover, which quick fixes are renames), the
 * executor's per-version builder table and the weaver (port names).
 *
 * <p>Why a Java table and not a resource file: the executor and the weaver refer to entries and
 * port names from code, so a typo is a compile error rather than a lookup that fails at run time;
 * nothing parses at start-up; and the run-time side gets it without a resource loader. It is built
 * once, when {@link org.miron.bt.nodes.NodeCatalogue} is first used, from records that cannot
 * change. CatalogueGrammarTest fails when the grammar's element keywords and the table disagree.
 *
 * <p>For code that builds or writes trees: {@code NodeCatalogue.builtin(tag, version)} says whether
 * an element is a built-in of that version and gives its entry; {@code NodeModel.tag()} folds other
 * spellings (RetryUntilSuccesful) into one key for a per-version factory table; {@code children()}
 * and {@code ports(version)} with {@code PortModel.required()} and {@code accepts(literal)} are the
 * load-time checks; the port-name constants of {@link org.miron.bt.nodes.BuiltinNodes} replace
 * hand-typed names such as "num_cycles".
 *
 * <p>Nodes the application registers are described by the file itself: {@link
 * org.miron.bt.nodes.NodeDeclarations} reads the {@code <TreeNodesModel>} of a file and its
 * includes (ports with their direction), for the IDE, the key checks of the validator and the
 * executor (a skill's declared output ports are written, not sent).
 *
 * <p>Adding a built-in node: one entry in {@link org.miron.bt.nodes.BuiltinNodes} (and its keyword
 * and rule in Bt.xtext, which the test demands), and its executor class in the executor's builder
 * table (org.miron.executor's BuiltinFactories, whose BuiltinFactoriesTest fails until it is there;
 * the executor's README, "Adding a built-in node").
 */
package org.miron.bt.nodes;
