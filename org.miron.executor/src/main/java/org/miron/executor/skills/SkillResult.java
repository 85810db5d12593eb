package org.miron.executor.skills;

import java.util.Map;

/** The skill interface's answer: outcome, result value and out-attributes. */
public record SkillResult(Outcome outcome, Object value, Map<String, Object> outputs) {

    /** SmartSoft's skill results. */
    public enum Outcome {
        SUCCESS, ERROR, ABORT
    }

    public SkillResult {
        outputs = outputs == null ? Map.of() : Map.copyOf(outputs);
    }

    public static SkillResult of(Outcome outcome) {
        return new SkillResult(outcome, null, Map.of());
    }
}
