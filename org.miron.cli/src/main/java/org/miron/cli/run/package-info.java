/**
 * {@code miron run}: the MIRoN side of a robot in one process (issue 39). {@link org.miron.cli.run.RunModel}
 * generates the {@code .miron} into a temporary folder, as {@code miron generate} would, and
 * refuses a model with errors as {@code miron check} does; {@link org.miron.cli.run.RobotSide}
 * composes the broker, requirement monitors, RoQME provider, optional DDS bridge and engine, in that
 * order, all or nothing. The components still talk over the broker's loopback sockets, exactly as
 * separate processes do (in-process links without sockets are a later step of the issue): external
 * peers cannot tell one process from several. {@code miron demo} keeps its own set-up, which also
 * starts the skill mock, executor and player and narrates them.
 */
package org.miron.cli.run;
