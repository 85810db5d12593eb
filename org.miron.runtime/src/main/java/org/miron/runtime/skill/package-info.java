/**
 * The skill interface side: the executor's client (REQ, results on SUB) and the mock SmartSoft
 * ComponentSkillInterface, whose skills take a table's times ({@link org.miron.runtime.skill.TableSkills})
 * or act on a simulated world (org.miron.runtime.sim.LiveWorld), both a {@link org.miron.runtime.skill.SkillBehaviour}.
 */
package org.miron.runtime.skill;
