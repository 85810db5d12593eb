package org.miron.executor.v4;

import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * One tick as both sides report it: the root status, the leaf executions in order and the
 * blackboard values asked for (as text, null when unset). A tick that failed has an error instead
 * of a status (the message differs between the two, so only its presence is compared).
 */
@JsonIgnoreProperties(ignoreUnknown = true)
@JsonInclude(JsonInclude.Include.NON_NULL)
record TickRecord(int tick, String status, List<String> trace, Map<String, String> blackboard, String error) {

    /** What must be equal on both sides. */
    String comparable() {
        if (error != null) {
            return "tick " + tick + ": ERROR";
        }
        return "tick " + tick + ": " + status + " " + trace + " " + blackboard;
    }
}
