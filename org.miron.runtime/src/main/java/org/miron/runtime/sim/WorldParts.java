package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.TypeCheck.Symbol;
import org.miron.runtime.sim.WorldModel.Measure;
import org.miron.runtime.sim.WorldModel.Outcome;
import org.miron.runtime.sim.WorldModel.Place;
import org.miron.runtime.sim.WorldModel.Process;
import org.miron.runtime.sim.WorldModel.Publication;
import org.miron.runtime.sim.WorldModel.SkillModel;
import org.miron.runtime.sim.WorldModel.Target;

/** The parts of a world file that hold expressions: skills, processes, published contexts, measures. */
final class WorldParts {
    private static final Set<String> SKILL = Set.of("target", "requires", "duration", "start", "perSecond", "end", "events", "outcomes");
    private static final Set<String> PROCESS = Set.of("while", "perSecond", "rate", "every", "do", "events", "abortSkill");
    private static final Set<String> MEASURE_KINDS = Set.of("count", "integral", "fraction", "final", "mean");

    private final Diagnostics d;
    private final ExprFactory exprs;
    private final Map<String, Symbol> scope;
    private final List<String> events;
    private final WorldEnv env;
    private final Map<String, Place> places;
    private final Set<String> emitted = new HashSet<>();
    private SkillModel anySkill;

    WorldParts(Diagnostics d, ExprFactory exprs, Map<String, Symbol> scope, List<String> events, WorldEnv env,
            Map<String, Place> places) {
        this.d = d;
        this.exprs = exprs;
        this.scope = scope;
        this.events = events;
        this.env = env;
        this.places = places;
    }

    SkillModel anySkill() {
        return anySkill;
    }

    Map<String, SkillModel> skills(JsonNode node) {
        Map<String, SkillModel> out = new LinkedHashMap<>();
        node.fields().forEachRemaining(f -> {
            String name = f.getKey();
            String at = PositionedJson.child("/skills", name);
            Set<String> ports = env.skills().get(name);
            if (ports == null && !name.equals("*")) {
                d.name(at, "unknown-skill", "unknown skill '" + name + "': the behaviour tree pushes " + env.skills().keySet());
                return;
            }
            SkillModel s = skill(name, at, f.getValue(), ports == null ? Set.of() : ports);
            if (s != null && name.equals("*")) {
                anySkill = s;
            } else if (s != null) {
                out.put(name, s);
            }
        });
        if (!node.has("*")) {
            for (String skill : env.skills().keySet()) {
                if (!node.has(skill)) {
                    d.error("/skills", "missing-skill", "the behaviour tree pushes '" + skill
                            + "', which the world does not model (add it, or a \"*\" entry for every other skill)");
                }
            }
        }
        return out;
    }

    private SkillModel skill(String name, String at, JsonNode def, Set<String> ports) {
        unknownFields(def, at, SKILL);
        Map<String, Symbol> local = new LinkedHashMap<>(scope);
        for (String port : ports) {
            local.putIfAbsent(port, new Symbol(SimType.ANY, false));
        }
        Target target = null;
        JsonNode t = def.get("target");
        if (t != null) {
            if (t.isTextual()) {
                target = new Target(t.asText(), null, null);
                portExists(t.asText(), ports, at + "/target", name);
            } else if (t.path("x").isTextual() && t.path("y").isTextual()) {
                target = new Target(null, t.get("x").asText(), t.get("y").asText());
                portExists(target.x(), ports, at + "/target/x", name);
                portExists(target.y(), ports, at + "/target/y", name);
            } else {
                d.error(at + "/target", "type", "target: the input naming a place (\"goal\"), or the inputs of the coordinates ({\"x\": \"x\", \"y\": \"y\"})");
            }
            local.put("distance", new Symbol(SimType.NUMBER, false));
        }
        Expr requires = exprs.compile(def.get("requires"), at + "/requires", local, SimType.BOOLEAN, false);
        Expr duration = exprs.compile(def.has("duration") ? def.get("duration") : null, at + "/duration", local, SimType.NUMBER, false);
        if (!def.has("duration")) {
            d.error(at, "missing", "a skill needs a duration (seconds, an expression)");
        }
        Expr start = exprs.compile(def.get("start"), at + "/start", local, null, true);
        Map<String, Expr> perSecond = rates(def.path("perSecond"), at + "/perSecond", local);
        Expr end = exprs.compile(def.get("end"), at + "/end", local, null, true);
        List<String> ev = events(def.path("events"), at + "/events");
        List<Outcome> outcomes = new ArrayList<>();
        for (int i = 0; i < def.path("outcomes").size(); i++) {
            JsonNode o = def.get("outcomes").get(i);
            String oat = at + "/outcomes/" + i;
            String result = o.path("result").asText("SUCCESS");
            if (!result.equals("SUCCESS") && !result.equals("ERROR")) {
                d.error(oat + "/result", "value", "result is SUCCESS or ERROR, not '" + result + "'");
            }
            Expr p = exprs.compile(o.has("probability") ? o.get("probability") : null, oat + "/probability", local, null, false);
            if (p != null && p.type().kind() != SimType.Kind.NUMBER && p.type().kind() != SimType.Kind.BOOLEAN) {
                d.error(oat + "/probability", "type", "probability is a number in [0,1] or a condition");
            }
            outcomes.add(new Outcome(p, result.equals("SUCCESS"), exprs.compile(o.get("do"), oat + "/do", local, null, true),
                    events(o.path("events"), oat + "/events")));
        }
        return new SkillModel(name, target, requires, duration, start, perSecond, end, ev, outcomes);
    }

    private void portExists(String port, Set<String> ports, String at, String skill) {
        if (!ports.isEmpty() && !ports.contains(port)) {
            d.error(at, "unknown-input", "skill " + skill + " has no input '" + port + "' in the tree (inputs: " + ports + ")");
        }
    }

    private Map<String, Expr> rates(JsonNode node, String at, Map<String, Symbol> local) {
        Map<String, Expr> out = new LinkedHashMap<>();
        node.fields().forEachRemaining(f -> {
            String pointer = PositionedJson.child(at, f.getKey());
            Symbol s = scope.get(f.getKey());
            if (s == null || !s.writable()) {
                d.name(pointer, "unknown-name", "'" + f.getKey() + "' is no state variable");
                return;
            }
            if (s.type().kind() != SimType.Kind.NUMBER) {
                d.error(pointer, "type", "'" + f.getKey() + "' is " + s.type() + ": only numbers change per second");
                return;
            }
            Expr e = exprs.compile(f.getValue(), pointer, local, SimType.NUMBER, false);
            if (e != null) {
                out.put(f.getKey(), e);
            }
        });
        return out;
    }

    private List<String> events(JsonNode node, String at) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < node.size(); i++) {
            String e = node.get(i).asText();
            if (!events.contains(e)) {
                d.error(at + "/" + i, "unknown-event", "unknown event '" + e + "' (declared events: " + events + ")");
            } else {
                out.add(e);
                emitted.add(e);
            }
        }
        return out;
    }

    List<Process> processes(JsonNode node) {
        List<Process> out = new ArrayList<>();
        node.fields().forEachRemaining(f -> {
            String at = PositionedJson.child("/processes", f.getKey());
            JsonNode def = f.getValue();
            unknownFields(def, at, PROCESS);
            Long every = null;
            if (def.has("every")) {
                try {
                    every = Durations.parseMs(def.get("every").asText());
                    if (every <= 0) {
                        throw new IllegalArgumentException("every must be positive");
                    }
                } catch (IllegalArgumentException e) {
                    d.error(at + "/every", "value", e.getMessage());
                }
            }
            Expr rate = exprs.compile(def.get("rate"), at + "/rate", scope, SimType.NUMBER, false);
            if (def.has("rate") && def.has("every")) {
                d.error(at, "value", "a process occurs at a rate or every period, not both");
            }
            out.add(new Process(f.getKey(), exprs.compile(def.get("while"), at + "/while", scope, SimType.BOOLEAN, false),
                    rates(def.path("perSecond"), at + "/perSecond", scope), rate, every,
                    exprs.compile(def.get("do"), at + "/do", scope, null, true), events(def.path("events"), at + "/events"),
                    def.path("abortSkill").asBoolean(false)));
        });
        return out;
    }

    List<Publication> publications(JsonNode node) {
        List<Publication> out = new ArrayList<>();
        node.fields().forEachRemaining(f -> {
            String name = f.getKey();
            String at = PositionedJson.child("/contexts", name);
            JsonNode def = f.getValue();
            RoqmeModel.Type type = env.contexts().get(name);
            if (type == null) {
                d.name(at, "unknown-context", "unknown context '" + name + "': the model receives " + env.contexts().keySet());
                return;
            }
            if (type.kind().equals("eventtype")) {
                String e = def.path("event").asText("");
                if (!events.contains(e)) {
                    d.error(at + "/event", "unknown-event", "context " + name + " is an event: name one of the world's events " + events);
                    return;
                }
                out.add(new Publication(name, type, null, e, null));
                return;
            }
            SimType wanted = WorldReader.typeOf(type);
            if (wanted == null) {
                d.error(at, "type", "context " + name + " is a " + type.kind() + ": the world publishes numbers, booleans, enums and events");
                return;
            }
            Expr value = exprs.compile(def.get("value"), at + "/value", scope, wanted, false);
            if (!def.has("value")) {
                d.error(at, "missing", "a published context needs its value (an expression of the state)");
            }
            Long every = null;
            if (def.has("every")) {
                try {
                    every = Durations.parseMs(def.get("every").asText());
                } catch (IllegalArgumentException e) {
                    d.error(at + "/every", "value", e.getMessage());
                }
            }
            if (value != null) {
                out.add(new Publication(name, type, value, null, every));
            }
        });
        return out;
    }

    List<Measure> measures(JsonNode node) {
        List<Measure> out = new ArrayList<>();
        node.fields().forEachRemaining(f -> {
            String at = PositionedJson.child("/measures", f.getKey());
            JsonNode def = f.getValue();
            List<String> kinds = new ArrayList<>();
            def.fieldNames().forEachRemaining(k -> {
                if (MEASURE_KINDS.contains(k)) {
                    kinds.add(k);
                }
            });
            if (kinds.size() != 1) {
                d.error(at, "measure", "a measure has exactly one of " + MEASURE_KINDS + ", it has " + kinds);
                return;
            }
            String kind = kinds.get(0);
            String pointer = at + "/" + kind;
            Measure.Kind k = Measure.Kind.valueOf(kind.toUpperCase(java.util.Locale.ROOT));
            String unit = def.path("unit").asText("");
            String better = def.path("better").asText("");
            if (!better.isEmpty() && !better.equals("higher") && !better.equals("lower")) {
                d.error(at + "/better", "value", "better is higher or lower, not '" + better + "'");
            }
            String text = def.get(kind).asText();
            if (k == Measure.Kind.COUNT && events.contains(text)) {
                if (!emitted.contains(text)) {
                    d.error(pointer, "measure-over-nothing", "no skill, outcome or process emits event '" + text + "': the count is always 0");
                    return;
                }
                out.add(new Measure(f.getKey(), k, null, text, unit, better));
                return;
            }
            SimType wanted = k == Measure.Kind.COUNT || k == Measure.Kind.FRACTION ? SimType.BOOLEAN : null;
            Expr e = exprs.compile(def.get(kind), pointer, scope, wanted, false);
            if (e == null) {
                return;
            }
            if (k != Measure.Kind.COUNT && e.type().kind() != SimType.Kind.NUMBER && e.type().kind() != SimType.Kind.BOOLEAN) {
                d.error(pointer, "type", "'" + e.source() + "' is " + e.type() + ": a measure aggregates numbers or conditions");
                return;
            }
            if (e.reads().stream().noneMatch(n -> !n.equals("random"))) {
                d.error(pointer, "measure-over-nothing", "'" + e.source() + "' reads no state, parameter or event: it measures nothing");
                return;
            }
            out.add(new Measure(f.getKey(), k, e, null, unit, better));
        });
        return out;
    }

    private void unknownFields(JsonNode def, String at, Set<String> known) {
        if (!def.isObject()) {
            d.error(at, "type", "expected an object");
            return;
        }
        def.fieldNames().forEachRemaining(f -> {
            if (!known.contains(f)) {
                d.name(PositionedJson.child(at, f), "unknown-field", "unknown field '" + f + "' (known: " + new java.util.TreeSet<>(known) + ")");
            }
        });
    }
}
