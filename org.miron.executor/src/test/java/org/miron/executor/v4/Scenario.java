package org.miron.executor.v4;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.databind.ObjectMapper;

/** A scenario file (see btcpp4_oracle.py): the tree, the scripted leaves, how many ticks. */
@JsonIgnoreProperties(ignoreUnknown = true)
record Scenario(String tree, int ticks, String mode, Map<String, List<String>> actions,
        Map<String, List<String>> conditions, List<String> blackboard) {

    static Scenario read(Path file) throws IOException {
        return new ObjectMapper().readValue(file.toFile(), Scenario.class);
    }

    boolean exactlyOnce() {
        return "exactly_once".equals(mode);
    }

    Map<String, List<String>> actionsOrEmpty() {
        return actions == null ? Map.of() : actions;
    }

    Map<String, List<String>> conditionsOrEmpty() {
        return conditions == null ? Map.of() : conditions;
    }

    List<String> blackboardOrEmpty() {
        return blackboard == null ? List.of() : blackboard;
    }
}
