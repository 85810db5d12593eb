package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.util.List;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

/**
 * Turns bus messages into {@link InputState} updates, validating them against the io.json:
 * {@code roqme.estimate}, {@code roqme.context} and {@code miron.override.<vp>}
 * (body {@code {"value": <one of the varpoint's values>}} pins it, {@code {"value": null}} releases it).
 */
public final class InputDecoder {
    private final IoModel model;
    private final InputState state;

    public InputDecoder(IoModel model, InputState state) {
        this.model = model;
        this.state = state;
    }

    public void apply(String topic, byte[] body) throws BadInputException {
        if (topic.equals(Topics.ESTIMATE)) {
            estimate(parse(body));
        } else if (topic.equals(Topics.CONTEXT)) {
            context(parse(body));
        } else if (topic.startsWith(Topics.OVERRIDE_PREFIX)) {
            override(topic.substring(Topics.OVERRIDE_PREFIX.length()), parse(body));
        } else {
            throw new BadInputException(BadInputException.Kind.UNKNOWN, "unknown topic " + topic);
        }
    }

    private static JsonNode parse(byte[] body) throws BadInputException {
        JsonNode node;
        try {
            node = Json.MAPPER.readTree(body);
        } catch (IOException e) {
            throw new BadInputException(BadInputException.Kind.MALFORMED, "not JSON: " + firstLine(e.getMessage()));
        }
        if (node == null || !node.isObject()) {
            throw new BadInputException(BadInputException.Kind.MALFORMED, "body is not a JSON object");
        }
        return node;
    }

    private void estimate(JsonNode msg) throws BadInputException {
        InputSpec in = find("metric", msg);
        JsonNode v = msg.get("value");
        if (v == null || !v.isNumber() || !Double.isFinite(v.asDouble()) || v.asDouble() < 0 || v.asDouble() > 1) {
            throw type(in, "a number in [0,1]", v);
        }
        state.setMetric(in, v.asDouble());
    }

    private void context(JsonNode msg) throws BadInputException {
        List<InputSpec> hits = matches("context", msg);
        if (hits.isEmpty()) {
            // The robot publishes its contexts for the RoQME provider, which reads them all (and
            // counts the ones its model does not declare); the engine reads only the few its rules
            // name. Any other context is not for it: neither an error nor a warning.
            return;
        }
        InputSpec in = only("context", msg, hits);
        JsonNode declared = msg.get("type");
        if (declared != null && !declared.isNull() && !declared.asText().equals(in.roqmeType())) {
            throw new BadInputException(BadInputException.Kind.TYPE, "context " + in.name() + " is "
                    + in.roqmeType() + ", message says " + declared.asText());
        }
        JsonNode v = msg.get("value");
        switch (in.roqmeType()) {
            case "number":
                if (v == null || !v.isNumber() || !Double.isFinite(v.asDouble())) {
                    throw type(in, "a number", v);
                }
                state.setContext(in, in.type().equals("int") ? (Object) v.asInt() : (Object) v.asDouble());
                break;
            case "boolean":
                if (v == null || !v.isBoolean()) {
                    throw type(in, "a boolean", v);
                }
                state.setContext(in, v.asBoolean());
                break;
            case "enum":
                int index = v != null && v.isTextual() ? in.literals().indexOf(v.asText()) : -1;
                if (index < 0) {
                    throw type(in, "one of " + in.literals(), v);
                }
                state.setContext(in, index);
                break;
            case "event":
                state.setContext(in, Boolean.TRUE);
                break;
            default:
                throw new BadInputException(BadInputException.Kind.UNKNOWN, "unsupported context type " + in.roqmeType());
        }
    }

    private void override(String name, JsonNode msg) throws BadInputException {
        VariationPoint vp = model.varpoint(name).orElseThrow(
                () -> new BadInputException(BadInputException.Kind.UNKNOWN, "unknown varpoint " + name));
        if (!msg.has("value")) {
            throw new BadInputException(BadInputException.Kind.MALFORMED, "override of " + name + " has no 'value'");
        }
        JsonNode v = msg.get("value");
        if (v.isNull()) {
            state.setOverride(vp, null);
            return;
        }
        int index = vp.indexOf(v);
        if (index < 0) {
            throw new BadInputException(BadInputException.Kind.TYPE,
                    "override value " + v + " is not a value of varpoint " + name);
        }
        state.setOverride(vp, index);
    }

    /** Matches name and namespace; a message without namespace matches by name when unambiguous. */
    private InputSpec find(String kind, JsonNode msg) throws BadInputException {
        return only(kind, msg, matches(kind, msg));
    }

    /** The one input the message names, else unknown or ambiguous input. */
    private static InputSpec only(String kind, JsonNode msg, List<InputSpec> hits) throws BadInputException {
        JsonNode name = msg.get("name");
        JsonNode ns = msg.get("namespace");
        if (hits.size() != 1) {
            throw new BadInputException(BadInputException.Kind.UNKNOWN, (hits.isEmpty() ? "unknown " : "ambiguous ")
                    + kind + " " + (ns == null ? "" : ns.asText() + "::") + name.asText());
        }
        return hits.get(0);
    }

    /** The inputs of this kind the message names (a message without namespace: all of that name). */
    private List<InputSpec> matches(String kind, JsonNode msg) throws BadInputException {
        JsonNode name = msg.get("name");
        if (name == null || !name.isTextual()) {
            throw new BadInputException(BadInputException.Kind.MALFORMED, kind + " message without a 'name'");
        }
        JsonNode ns = msg.get("namespace");
        return model.inputs().stream()
                .filter(i -> i.kind().equals(kind) && i.name().equals(name.asText()))
                .filter(i -> ns == null || ns.isNull() || i.namespace().equals(ns.asText()))
                .toList();
    }

    private static BadInputException type(InputSpec in, String expected, JsonNode got) {
        return new BadInputException(BadInputException.Kind.TYPE,
                in.kind() + " " + in.name() + " needs " + expected + ", got " + got);
    }

    private static String firstLine(String s) {
        return s == null ? "" : s.lines().findFirst().orElse("");
    }
}
