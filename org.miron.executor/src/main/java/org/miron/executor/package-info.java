/**
 * The behaviour-tree executor (module org.miron.executor, which needs the BT language alone): runs a .bt file (or a woven .ext.xml) with BehaviorTree.CPP 3
 * semantics (the project's BT semantics reference: statuses, halting, every node of the BT language),
 * or BehaviorTree.CPP 4 semantics when the file has {@code <root BTCPP_format="4">}: SKIPPED,
 * pre/post-condition attributes, wake-ups, the version-4 nodes and the scripting language
 * (docs/bt-semantics.md, "Version 4").
 *
 * <h2>Using it</h2>
 * <pre>{@code
 * ActionRegistry actions = new ActionRegistry()
 *         .registerSync("objectdrop", ports -> NodeStatus.SUCCESS)
 *         .registerAsync("navigate", NavigateAction::new)      // RUNNING until done, told when halted
 *         .registerVariantAction(variants)                      // <Action ID="VariantAction" .../>
 *         .registerDecorator("RateController", RateController::new) // <RateController hz="1">child</...>
 *         .registerControl("PriorityScheduler", Scheduler::new) // <Control ID="PriorityScheduler">...
 *         .setFallback(new SkillActionStrategy(skillClient));   // every other ID: push-skill requests
 * TreeContext context = new TreeContext();
 * context.addListener(new ConsoleTracePrinter());                // status changes as they happen
 * Tree tree = new TreeBuilder(actions, context).build(Path.of("intralogistics.ext.xml"));
 * tree.feedBlackboardFrom(numbers);                              // miron.blackboard.<vp> values
 * tree.tickWhileRunning(Duration.ofMillis(100));
 * }</pre>
 * {@link org.miron.executor.skills.VariantSource} is the thread-safe hand-over point for the bus:
 * a subscriber publishes {@code miron.variant.<vp>} values into one, {@code miron.blackboard.<vp>}
 * values into another; {@link org.miron.executor.skills.SkillClient} is where a ZeroMQ client of
 * the SmartSoft skill interface plugs in.
 *
 * <h2>Version 4</h2>
 * {@link org.miron.executor.TreeBuilder} reads the version from the file and makes each built-in
 * with that version's factory table ({@code BuiltinFactories}: the *V4 classes where BT.CPP 4
 * changed a node's behaviour, the version-4 nodes), after checking its children and ports against
 * the catalogue of built-in nodes (org.miron.bt.nodes; {@code BuiltinChecks}); for version 4,
 * {@code V4Nodes} gives every node its {@code Conditions} (the _skipIf.._onHalted scripts, run by
 * {@link org.miron.executor.Node#executeTick()}). Scripts are parsed once by the BT
 * language ({@code BtScripts}) and compiled by {@code ScriptCompiler} into
 * {@link org.miron.executor.scripting.ScriptCode} closures; {@code ScriptOperators} and
 * {@link org.miron.executor.scripting.ScriptValues} hold BT.CPP 4's value rules. Enums for scripts are
 * registered on the {@link org.miron.executor.ActionRegistry}.
 *
 * <h2>Packages</h2>
 * Laid out by family, as BehaviorTree.CPP lays out its sources, so that a node's class is found
 * from its kind: this package holds what every tree needs (the tree and its builder and loader,
 * the node base classes, statuses, blackboard, ports, the action registry, the Java action
 * adapters); {@code controls}, {@code decorators} and {@code actions} hold the built-in nodes of
 * each kind, a {@code *V4} class beside the version-3 class it replaces; {@code scripting} holds
 * the version-4 script compiler and value rules; {@code skills} the leaves that reach outside the
 * tree (skill requests through {@link org.miron.executor.skills.SkillClient}, variant choices and
 * blackboard decisions through {@link org.miron.executor.skills.VariantSource}); {@code trace} the
 * status listener and the console trace. Nothing here knows the bus: org.miron.runtime's live
 * executor plugs a ZeroMQ skill client and the decision feed in.
 *
 * <h2>Design</h2>
 * {@link org.miron.executor.TreeBuilder} turns the EMF model into one runtime
 * {@link org.miron.executor.Node} per model node (one small class per node kind), built-ins by
 * their catalogue tag rather than their metamodel class, so a node the grammar maps onto a shared
 * class (AsyncSequence onto Sequence) still gets its own;
 * subtrees are expanded in place, each with its own {@link org.miron.executor.Blackboard}
 * remapped to its parent's. Ports are read at tick time through
 * {@link org.miron.executor.Ports}. Ticks run on one thread; listeners are called on it.
 *
 * <h2>Where we differ from BehaviorTree.CPP 3, on purpose</h2>
 * <ul>
 * <li>Repeat and RetryUntilSuccessful tick their child at most
 * {@link org.miron.executor.TreeContext#maxLoopsPerTick()} times within one tick, then
 * return RUNNING and carry on at the next tick: Repeat(-1) over a child that always succeeds at
 * once no longer hangs the tree.</li>
 * <li>Timeout reads the clock when it is ticked (no timer thread): it fails on the first tick at
 * which msec have passed since its first tick, which makes it deterministic and testable.</li>
 * <li>Delay likewise: its child is ticked from the first tick at which delay_msec have passed
 * since its first tick (delay_msec="0" ticks the child at once, not on the next tick).</li>
 * <li>FallbackStar (no longer in BT.CPP 3) mirrors SequenceStar: after a SUCCESS it keeps its
 * position.</li>
 * <li>A tree ID used as a tag is a SubTree (BT.CPP 4 style); a value in braces names the parent key.</li>
 * <li>A Parallel threshold outside 1..children (after counting negative values from the number
 * of children) is an error: at build time when literal, at tick time when read from the blackboard.</li>
 * <li>Numeric ports reject fractions ("3.5" is not an int), where BT.CPP would truncate.</li>
 * </ul>
 */
package org.miron.executor;
