/**
 * The closed-loop mission simulator (docs/simulator.md): a world file ({@link org.miron.runtime.sim.WorldReader},
 * checked with positions) says how skills and processes act on the robot's state and which state is
 * published as which RoQME context; {@link org.miron.runtime.sim.Simulation} runs the behaviour tree,
 * the RoQME provider, the engine's decisions and the {@link org.miron.runtime.sim.World} on one
 * virtual clock, and {@link org.miron.runtime.sim.Comparison} compares policies over seeded runs.
 * {@link org.miron.runtime.sim.WorldDriver} steps a world and its publications for both clocks: the
 * simulator's virtual one and the wall clock of {@link org.miron.runtime.sim.LiveWorld}, the mock
 * skill interface's skills acting on a world that publishes the contexts on the bus.
 * Expressions are BehaviorTree.CPP 4 scripts, statically typed by {@code TypeCheck}.
 */
package org.miron.runtime.sim;
