/**
 * {@code miron run}: the MIRoN side of a robot in one process (issue 39). {@link org.miron.cli.run.RunModel}
 * takes the {@code .miron}'s generation from the {@link org.miron.cli.run.GeneratedCache} while the model
 * and all it imports are unchanged, or has {@code miron generate} make it in a JVM of its own
 * ({@link org.miron.cli.run.GenerationProcess}), refusing a model with errors as {@code miron check}
 * does: the robot's process loads no Xtext. {@link org.miron.cli.run.RobotSide} composes the broker,
 * requirement monitors, RoQME provider, optional DDS bridge and engine, in that order, all or
 * nothing; the components reach the broker through its local links (no sockets), and external peers
 * see the same wire as with separate processes. {@code miron demo} keeps its own set-up, which also
 * starts the skill mock, executor and player and narrates them.
 */
package org.miron.cli.run;
