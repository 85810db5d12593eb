package org.miron.runtime.roqme.model;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;

/**
 * The RoQME runtime model {@code name.roqme.json} (format 1) as written by {@code miron generate}:
 * plain records bound by Jackson, field names exactly as in docs/roqme-model.md. Expressions stay
 * JSON trees; {@link org.miron.runtime.roqme.expr.Compiler} turns them into evaluators.
 */
@JsonIgnoreProperties(ignoreUnknown = true)
public record RoqmeModel(int format, String model, String source, List<Variable> contexts,
        List<Variable> params, List<Variable> vars, List<Timer> timers, List<Belief> beliefs,
        List<Observation> observations) {

    public RoqmeModel {
        contexts = nonNull(contexts);
        params = nonNull(params);
        vars = nonNull(vars);
        timers = nonNull(timers);
        beliefs = nonNull(beliefs);
        observations = nonNull(observations);
    }

    private static <T> List<T> nonNull(List<T> l) {
        return l == null ? List.of() : List.copyOf(l);
    }

    /** A context, param or var; {@code derived}/{@code init} only for derived contexts and vars. */
    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Variable(String id, String name, String namespace, String at, Type type, JsonNode derived,
            JsonNode init, @com.fasterxml.jackson.annotation.JsonProperty("default") JsonNode defaultValue) {
    }

    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Type(String kind, List<String> literals, Double lower, Double upper, Integer cardinality,
            String unit) {
    }

    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Timer(String id, String name, String namespace, String at, Long periodMs, String schedule,
            long offsetMs, boolean onetime, boolean paused) {
    }

    /** A property or beliefvar; {@code expr} for a property defined by an expression. */
    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Belief(String id, String name, String namespace, String at, String kind, Double reference,
            Long survivalMs, JsonNode expr, Type type) {
        public double ref() {
            return reference == null ? 0.5 : reference;
        }

        public boolean isProperty() {
            return !"beliefvar".equals(kind);
        }
    }

    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Observation(String id, String name, String namespace, String at, JsonNode pattern,
            List<Action> actions, String doc) {
        public Observation {
            actions = actions == null ? List.of() : List.copyOf(actions);
        }
    }

    /** One action; which fields are set depends on {@code kind} (see the contract). */
    @JsonIgnoreProperties(ignoreUnknown = true)
    public record Action(String kind, String belief, String strength, Long survivalMs, String var, JsonNode value,
            String timer) {
    }
}
