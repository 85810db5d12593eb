package org.miron.runtime.skill;

import java.util.Map;

/**
 * How long the executor waits for a pushed skill's result before giving up on it: per skill name,
 * {@code "*"} for the others, {@link #DEFAULT_MS} without either. Without a deadline a skill whose
 * result is lost (the skill interface died, a message dropped) would keep its node RUNNING forever.
 */
public final class SkillDeadlines {
    public static final long DEFAULT_MS = 120_000;
    private final Map<String, Long> millis;

    /** @param millis skill name (or {@code *}) → deadline in ms */
    public SkillDeadlines(Map<String, Long> millis) {
        for (Map.Entry<String, Long> e : millis.entrySet()) {
            if (e.getValue() == null || e.getValue() <= 0) {
                throw new IllegalArgumentException("skill deadline of " + e.getKey() + " must be > 0 ms");
            }
        }
        this.millis = Map.copyOf(millis);
    }

    public static SkillDeadlines defaults() {
        return new SkillDeadlines(Map.of());
    }

    public long forSkill(String skill) {
        Long ms = millis.get(skill);
        return ms != null ? ms : millis.getOrDefault("*", DEFAULT_MS);
    }
}
