package org.miron.executor.skills;

import java.util.Map;

/** A push-skill request: the skill's name (the action ID) and its in-attributes. */
public record SkillRequest(String name, Map<String, Object> inAttributes) {
    public SkillRequest {
        inAttributes = Map.copyOf(inAttributes);
    }
}
