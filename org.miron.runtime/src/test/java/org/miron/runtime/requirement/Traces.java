package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.miron.runtime.Json;

/**
 * Hand-made requirement models for the monitor tests: signals {@code x} (a number context), {@code a},
 * {@code b} (Boolean contexts), {@code e} (an event context), {@code p} (a property) and {@code mode}
 * (an enum varpoint {@code slow, fast}, starting slow), and formulas written as JSON trees.
 */
final class Traces {
    private Traces() {
    }

    static ObjectNode model(JsonNode... formulas) {
        ObjectNode root = Json.object();
        root.put("format", 1);
        root.put("model", "t");
        ArrayNode s = root.putArray("signals");
        s.add(context("x", "number"));
        s.add(context("a", "boolean"));
        s.add(context("b", "boolean"));
        s.add(context("e", "event"));
        ObjectNode p = s.addObject();
        p.put("name", "p").put("kind", "property").put("property", "p").put("param", "param_p");
        ObjectNode vp = s.addObject();
        vp.put("name", "mode").put("kind", "varpoint").put("varpoint", "mode").put("type", "enum").put("initial", 0);
        vp.putArray("values").add("slow").add("fast");
        ArrayNode r = root.putArray("requirements");
        for (int i = 0; i < formulas.length; i++) {
            ObjectNode q = r.addObject();
            q.put("name", "r" + i).put("line", i + 1).put("column", 1).put("text", formulas[i].toString());
            q.putNull("probability");
            q.putArray("reads");
            q.set("formula", formulas[i]);
        }
        return root;
    }

    private static ObjectNode context(String name, String type) {
        ObjectNode c = Json.object();
        c.put("name", name).put("kind", "context").put("context", name).put("roqmeType", type).put("param", "param_" + name);
        return c;
    }

    static RequirementMonitors monitors(JsonNode... formulas) {
        return new RequirementMonitors(RequirementModel.parse(model(formulas)));
    }

    // ---- state formulas: the io.json expression language

    static ObjectNode state(JsonNode expr) {
        ObjectNode o = Json.object();
        o.set("state", expr);
        o.putArray("reads");
        return o;
    }

    static ObjectNode param(String signal) {
        return Json.object().put("param", "param_" + signal);
    }

    static ObjectNode constant(double v) {
        return Json.object().put("const", v);
    }

    static ObjectNode cmp(String op, String signal, double v) {
        return op(op, param(signal), constant(v));
    }

    /** A Boolean context as a state formula. */
    static ObjectNode is(String signal) {
        return state(param(signal));
    }

    static ObjectNode x(String op, double v) {
        return state(cmp(op, "x", v));
    }

    static ObjectNode modeIs(int index) {
        return state(op("=", Json.object().put("index", "mode"), constant(index)));
    }

    static ObjectNode op(String op, JsonNode... args) {
        ObjectNode o = Json.object();
        o.put("op", op);
        ArrayNode a = o.putArray("args");
        for (JsonNode x : args) {
            a.add(x);
        }
        return o;
    }

    static ObjectNode temporal(String op, Long withinMs, JsonNode arg) {
        ObjectNode o = op(op, arg);
        if (withinMs != null) {
            o.put("within", withinMs);
        }
        return o;
    }

    static ObjectNode always(JsonNode arg) {
        return temporal("always", null, arg);
    }

    static ObjectNode implies(JsonNode a, JsonNode b) {
        return op("implies", a, b);
    }

    static ObjectNode eventually(long within, JsonNode arg) {
        return temporal("eventually", within, arg);
    }

    static List<String> verdicts(List<RequirementResult> results) {
        return results.stream().map(r -> r.verdict().id()).toList();
    }
}
