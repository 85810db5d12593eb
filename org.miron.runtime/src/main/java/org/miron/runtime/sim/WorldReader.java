package org.miron.runtime.sim;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.TypeCheck.Symbol;
import org.miron.runtime.sim.WorldModel.Measure;
import org.miron.runtime.sim.WorldModel.Place;
import org.miron.runtime.sim.WorldModel.Publication;
import org.miron.runtime.sim.WorldModel.StateVar;

/**
 * Reads and checks a world file (docs/simulator.md) against the tree's skills and the model's
 * contexts; every problem is reported with its JSON pointer and line:col before anything runs.
 * Skills, processes and the rest are read by {@link WorldParts}.
 */
public final class WorldReader {
    static final Set<String> TOP = Set.of("$schema", "description", "places", "distances", "start", "state", "parameters",
            "events", "skills", "processes", "contexts", "measures", "restartDelay");
    /** Read-only names every expression may use. */
    static final List<String> BUILTINS = List.of("time", "skill", "place", "random");

    private WorldReader() {
    }

    public static WorldModel read(Path file, WorldEnv env) throws WorldException, IOException {
        return read(Files.readString(file), file.toString(), env);
    }

    public static WorldModel read(String text, String fileName, WorldEnv env) throws WorldException {
        PositionedJson json;
        try {
            json = PositionedJson.parse(text);
        } catch (JsonProcessingException e) {
            var l = e.getLocation();
            throw new WorldException(List.of(fileName + ":" + (l == null ? 1 : l.getLineNr()) + ":" + (l == null ? 1 : l.getColumnNr())
                    + ": error [world.syntax]: " + e.getOriginalMessage()));
        } catch (IOException e) {
            throw new WorldException(List.of(fileName + ":1:1: error [world.syntax]: " + e.getMessage()));
        }
        Diagnostics d = new Diagnostics(fileName, json);
        JsonNode root = json.root();
        if (!root.isObject()) {
            d.error("", "type", "a world file is a JSON object");
            throw new WorldException(d.lines());
        }
        root.fieldNames().forEachRemaining(f -> {
            if (!TOP.contains(f)) {
                d.name("/" + f, "unknown-field", "unknown field '" + f + "' (known: " + new java.util.TreeSet<>(TOP) + ")");
            }
        });
        Map<String, Place> places = places(root.path("places"), d);
        Map<String, Double> distances = distances(root.path("distances"), places, d);
        String start = null;
        if (root.has("start")) {
            start = root.get("start").asText();
            if (!places.containsKey(start)) {
                d.error("/start", "unknown-place", "unknown place '" + start + "' (places: " + places.keySet() + ")");
            }
        }
        List<StateVar> state = state(root.path("state"), places, d);
        Map<String, Object> parameters = new LinkedHashMap<>();
        root.path("parameters").fields().forEachRemaining(f -> {
            JsonNode v = f.getValue();
            if (v.isNumber()) {
                parameters.put(f.getKey(), v.asDouble());
            } else if (v.isBoolean()) {
                parameters.put(f.getKey(), v.asBoolean());
            } else {
                d.error("/parameters/" + f.getKey(), "type", "a parameter's initial value is a number or a boolean");
            }
        });
        List<String> events = new ArrayList<>();
        root.path("events").forEach(e -> events.add(e.asText()));
        Map<String, Symbol> scope = new LinkedHashMap<>();
        for (StateVar v : state) {
            scope.put(v.name(), new Symbol(v.type(), true));
        }
        parameters.forEach((name, v) -> {
            if (scope.containsKey(name)) {
                d.error("/parameters/" + name, "duplicate", "'" + name + "' is both a state variable and a parameter");
            }
            scope.put(name, new Symbol(v instanceof Boolean ? SimType.BOOLEAN : SimType.NUMBER, false));
        });
        List<String> skillNames = new ArrayList<>(env.skills().keySet());
        skillNames.add("");
        List<String> placeNames = new ArrayList<>(places.keySet());
        placeNames.add("");
        scope.put("time", new Symbol(SimType.NUMBER, false));
        scope.put("skill", new Symbol(SimType.enumOf("a skill name", skillNames), false));
        scope.put("place", new Symbol(SimType.enumOf("a place", placeNames), false));
        scope.put("random", new Symbol(SimType.NUMBER, false));
        ExprFactory exprs = new ExprFactory(d);
        WorldParts parts = new WorldParts(d, exprs, scope, events, env, places);
        var skills = parts.skills(root.path("skills"));
        var processes = parts.processes(root.path("processes"));
        List<Publication> publications = parts.publications(root.path("contexts"));
        List<Measure> measures = parts.measures(root.path("measures"));
        long restart = 1000;
        if (root.has("restartDelay")) {
            try {
                restart = Durations.parseMs(root.get("restartDelay").asText());
            } catch (IllegalArgumentException e) {
                d.error("/restartDelay", "value", e.getMessage());
            }
        }
        if (d.any()) {
            throw new WorldException(d.lines());
        }
        return new WorldModel(fileName, places, distances, start, state, parameters, events, skills,
                parts.anySkill(), processes, publications, measures, restart);
    }

    private static Map<String, Place> places(JsonNode node, Diagnostics d) {
        Map<String, Place> places = new LinkedHashMap<>();
        node.fields().forEachRemaining(f -> {
            JsonNode p = f.getValue();
            if (!p.path("x").isNumber() || !p.path("y").isNumber()) {
                d.error("/places/" + f.getKey(), "type", "a place needs numbers x and y (metres)");
                return;
            }
            places.put(f.getKey(), new Place(f.getKey(), p.get("x").asDouble(), p.get("y").asDouble()));
        });
        return places;
    }

    /** Path lengths that replace the straight line between two places, both ways: key {@code "a|b"}. */
    private static Map<String, Double> distances(JsonNode node, Map<String, Place> places, Diagnostics d) {
        Map<String, Double> out = new LinkedHashMap<>();
        for (int i = 0; i < node.size(); i++) {
            JsonNode e = node.get(i);
            String at = "/distances/" + i;
            boolean ok = true;
            for (String end : List.of("from", "to")) {
                if (!places.containsKey(e.path(end).asText())) {
                    d.error(at + "/" + end, "unknown-place", "unknown place '" + e.path(end).asText() + "' (places: " + places.keySet() + ")");
                    ok = false;
                }
            }
            if (!e.path("m").isNumber() || e.get("m").asDouble() < 0) {
                d.error(at + "/m", "type", "m: the path length in metres, a number ≥ 0");
                ok = false;
            }
            if (ok) {
                out.put(e.get("from").asText() + "|" + e.get("to").asText(), e.get("m").asDouble());
                out.put(e.get("to").asText() + "|" + e.get("from").asText(), e.get("m").asDouble());
            }
        }
        return out;
    }

    private static List<StateVar> state(JsonNode node, Map<String, Place> places, Diagnostics d) {
        List<StateVar> out = new ArrayList<>();
        node.fields().forEachRemaining(f -> {
            String name = f.getKey();
            String at = "/state/" + name;
            JsonNode v = f.getValue();
            if (BUILTINS.contains(name)) {
                d.error(at, "duplicate", "'" + name + "' is a built-in name: " + BUILTINS);
                return;
            }
            String type = v.path("type").asText("");
            JsonNode init = v.get("initial");
            switch (type) {
                case "number" -> {
                    if (init == null || !init.isNumber()) {
                        d.error(at + "/initial", "type", "a number state needs a numeric initial value");
                        return;
                    }
                    Double min = v.path("min").isNumber() ? v.get("min").asDouble() : null;
                    Double max = v.path("max").isNumber() ? v.get("max").asDouble() : null;
                    out.add(new StateVar(name, SimType.NUMBER, init.asDouble(), min, max));
                }
                case "boolean" -> {
                    if (init == null || !init.isBoolean()) {
                        d.error(at + "/initial", "type", "a boolean state needs true or false as initial value");
                        return;
                    }
                    out.add(new StateVar(name, SimType.BOOLEAN, init.asBoolean(), null, null));
                }
                case "enum", "place" -> {
                    Set<String> values = new LinkedHashSet<>();
                    if (type.equals("place")) {
                        values.addAll(places.keySet());
                    } else {
                        v.path("values").forEach(x -> values.add(x.asText()));
                    }
                    if (values.isEmpty()) {
                        d.error(at + "/values", "type", "an enum state needs its values");
                        return;
                    }
                    if (init == null || !values.contains(init.asText())) {
                        d.error(at + "/initial", type.equals("place") ? "unknown-place" : "type",
                                "the initial value must be one of " + values);
                        return;
                    }
                    out.add(new StateVar(name, SimType.enumOf((type.equals("place") ? "a place " : "enum ") + name,
                            List.copyOf(values)), init.asText(), null, null));
                }
                default -> d.error(at + "/type", "type", "type must be number, boolean, enum or place, not '" + type + "'");
            }
        });
        return out;
    }

    /** The world type of a RoQME context type, for publications; null when none fits. */
    static SimType typeOf(RoqmeModel.Type t) {
        return switch (t.kind()) {
            case "number", "time" -> SimType.NUMBER;
            case "boolean" -> SimType.BOOLEAN;
            case "enum" -> SimType.enumOf("enum " + t.literals(), t.literals());
            default -> null;
        };
    }
}
