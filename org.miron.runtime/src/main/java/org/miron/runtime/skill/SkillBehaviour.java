package org.miron.runtime.skill;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * What the mock's skills do once pushed: run for a table's fixed time ({@link TableSkills}) or act
 * on a simulated world (org.miron.runtime.sim.LiveWorld). Every call comes from the mock's one
 * thread, with the wall-clock time in ms.
 */
public interface SkillBehaviour extends AutoCloseable {
    /** Where a finished skill's result goes: published by the mock under the push's id. */
    interface Results {
        void publish(long id, String result, JsonNode resultValue, JsonNode outputs);
    }

    /** Called once, on the mock's thread, before anything else. */
    void start(Results results, long nowMs);

    /** A push-skill request: {@code skill} is its {@code skill} object (name, in-attribute). */
    void push(long id, JsonNode skill, long nowMs);

    /** A change-parameter query, already committed by the mock. */
    default void parameter(ParameterChange change, long nowMs) {
    }

    /** abort-current-skill: every running skill ends with ABORT. */
    void abortAll(long nowMs);

    /** The wall-clock time (ms) at which {@link #advance} has something to do next. */
    long nextDue(long nowMs);

    /** Does what is due by {@code nowMs}: finished skills' results, and whatever else the behaviour simulates. */
    void advance(long nowMs);

    @Override
    default void close() {
    }
}
