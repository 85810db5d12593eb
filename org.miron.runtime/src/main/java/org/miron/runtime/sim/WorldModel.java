package org.miron.runtime.sim;

import java.util.List;
import java.util.Map;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * A world file, checked (docs/simulator.md): what the simulator needs to act as the robot's
 * surroundings. Expressions are compiled; every name in it is known to exist.
 */
public record WorldModel(String source, Map<String, Place> places, Map<String, Double> distances, String start,
        List<StateVar> state, Map<String, Object> parameters, List<String> events, Map<String, SkillModel> skills,
        SkillModel anySkill, List<Process> processes, List<Publication> publications, List<Measure> measures,
        long restartDelayMs) {

    /** A named place on the map, in metres. */
    public record Place(String name, double x, double y) {
    }

    /** A state variable: its type, initial value (Double, Boolean or String) and, for numbers, bounds. */
    public record StateVar(String name, SimType type, Object initial, Double min, Double max) {
    }

    /**
     * How a skill acts on the world. {@code target}: where a moving skill goes (null: it stays);
     * {@code requires}: while false the skill fails (checked at start and at every step).
     */
    public record SkillModel(String name, Target target, Expr requires, Expr duration, Expr start,
            Map<String, Expr> perSecond, Expr end, List<String> events, List<Outcome> outcomes) {
    }

    /** The inputs naming a skill's destination: a place ({@code place}) or coordinates ({@code x}, {@code y}). */
    public record Target(String place, String x, String y) {
    }

    /** A possible end of a skill: drawn with its probability, in order; the first drawn wins. */
    public record Outcome(Expr probability, boolean success, Expr effect, List<String> events) {
    }

    /**
     * Something that happens by itself: rates of change while {@code whileExpr} holds, and/or an
     * occurrence at random (Poisson with {@code rate} per second) or every {@code everyMs}.
     */
    public record Process(String name, Expr whileExpr, Map<String, Expr> perSecond, Expr rate, Long everyMs,
            Expr effect, List<String> events, boolean abortSkill) {
    }

    /**
     * A RoQME context the world publishes: the value of an expression (every {@code everyMs}, or on
     * change when null) or an event.
     */
    public record Publication(String context, RoqmeModel.Type type, Expr value, String event, Long everyMs) {
    }

    /** What a run is judged by. */
    public record Measure(String name, Kind kind, Expr expr, String event, String unit, String better) {
        public enum Kind { COUNT, INTEGRAL, FRACTION, FINAL, MEAN }
    }
}
