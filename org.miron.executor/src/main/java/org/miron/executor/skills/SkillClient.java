package org.miron.executor.skills;

/**
 * The SmartSoft skill interface as the executor sees it. The real implementation sends push-skill
 * queries over ZeroMQ (REQ to :5557 or the broker's :5556) and completes the handle when the
 * matching skill-result arrives on :5558.
 */
@FunctionalInterface
public interface SkillClient {

    /** Sends a push-skill request and returns at once; called on the ticking thread. */
    SkillHandle pushSkill(SkillRequest request);
}
