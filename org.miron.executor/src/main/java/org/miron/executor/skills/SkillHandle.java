package org.miron.executor.skills;

import java.util.concurrent.CompletableFuture;

/** One pushed skill: its future result, and a way to abort it. */
public interface SkillHandle {

    /** Completed when the skill interface publishes the skill-result (any thread may complete it). */
    CompletableFuture<SkillResult> result();

    /** Asks the skill interface to abort this skill (abort-current-skill); must not block long. */
    void abort();

    static SkillHandle of(CompletableFuture<SkillResult> result, Runnable abort) {
        return new SkillHandle() {
            @Override
            public CompletableFuture<SkillResult> result() {
                return result;
            }

            @Override
            public void abort() {
                abort.run();
            }
        };
    }
}
