/**
 * The leaves through which a tree reaches the robot and the adaptation engine, behind interfaces
 * so that the executor needs no messaging library: a skill action sends a
 * {@link org.miron.executor.skills.SkillRequest} through a
 * {@link org.miron.executor.skills.SkillClient} and waits on its
 * {@link org.miron.executor.skills.SkillHandle} for the {@link org.miron.executor.skills.SkillResult};
 * a VariantAction runs the variant last published into a
 * {@link org.miron.executor.skills.VariantSource}, and {@link org.miron.executor.skills.BlackboardFeed}
 * copies numeric decisions into the blackboard. org.miron.runtime supplies the ZeroMQ client and
 * feeds the sources from the bus; tests supply fakes. A skill never receives an unresolved
 * {@code {key}}: an input whose key has no value fails the node before anything is sent.
 */
package org.miron.executor.skills;
