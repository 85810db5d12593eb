package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import org.miron.runtime.Json;

/**
 * The generated {@code name.io.json} (docs/io-json.md), with the .mzn/.dzn paths resolved.
 *
 * @param weights  the objective's weight policy, {@code need} (default) or {@code metric}
 * @param rules    the rules in priority order with their keep parameters (empty in files
 *                 generated before priorities: every rule is then always kept)
 * @param decision the structured {@code decision} section (the native backend's input), null in
 *                 files generated before it existed
 */
public record IoModel(String model, Path mzn, Path dzn, List<InputSpec> inputs, List<VariationPoint> varpoints,
        List<RuleSpec> rules, String weights, JsonNode decision) {
    private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");
    private static final List<String> ROQME_TYPES = List.of("boolean", "event", "enum", "number");
    private static final JsonNode BOOLEAN_VALUES = Json.MAPPER.createArrayNode().add(false).add(true);

    /** Reads and validates the file; any problem is an {@link IllegalArgumentException} naming it. */
    public static IoModel load(Path ioJson) {
        JsonNode root;
        try {
            root = Json.MAPPER.readTree(ioJson.toFile());
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read " + ioJson + ": " + e.getMessage(), e);
        }
        try {
            return parse(root, ioJson.toAbsolutePath().getParent());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(ioJson + ": " + e.getMessage(), e);
        }
    }

    static IoModel parse(JsonNode root, Path dir) {
        if (root == null || !root.isObject()) {
            throw new IllegalArgumentException("not a JSON object");
        }
        int format = root.path("format").asInt(1);
        if (format != 1) {
            throw new IllegalArgumentException("unsupported format " + format + " (expected 1)");
        }
        Path mzn = dir.resolve(required(root, "mzn"));
        if (!Files.isRegularFile(mzn)) {
            throw new IllegalArgumentException("model file not found: " + mzn);
        }
        String dznName = optional(root, "dzn");
        Path dzn = dznName == null ? null : dir.resolve(dznName);
        if (dzn != null && !Files.isRegularFile(dzn)) {
            throw new IllegalArgumentException("data file not found: " + dzn);
        }
        List<InputSpec> inputs = new ArrayList<>();
        JsonNode inputNodes = array(root, "inputs");
        for (int i = 0; i < inputNodes.size(); i++) {
            JsonNode in = inputNodes.get(i);
            inputs.add(within("inputs[" + i + "]", () -> input(in)));
        }
        List<VariationPoint> vps = new ArrayList<>();
        JsonNode varpointNodes = array(root, "varpoints");
        for (int i = 0; i < varpointNodes.size(); i++) {
            vps.add(varpoint(varpointNodes.get(i), "varpoints[" + i + "]"));
        }
        List<RuleSpec> rules = new ArrayList<>();
        JsonNode ruleNodes = root.get("rules");
        if (ruleNodes != null && !ruleNodes.isNull()) {
            JsonNode array = array(root, "rules");
            for (int i = 0; i < array.size(); i++) {
                JsonNode r = array.get(i);
                rules.add(within("rules[" + i + "]", () -> new RuleSpec(required(r, "name"), identifier(r, "keep"))));
            }
        }
        String model = optional(root, "model");
        JsonNode decision = root.get("decision");
        return new IoModel(model == null ? "model" : model, mzn, dzn, List.copyOf(inputs), List.copyOf(vps),
                List.copyOf(rules), root.path("weights").asText("need"), decision == null || decision.isNull() ? null : decision);
    }

    private static InputSpec input(JsonNode in) {
        String kind = required(in, "kind");
        if (!kind.equals("metric") && !kind.equals("context")) {
            throw new IllegalArgumentException("input kind '" + kind + "' is neither metric nor context");
        }
        boolean metric = kind.equals("metric");
        String type = oneOf(in, "type", metric ? List.of("float") : List.of("float", "bool", "int"));
        String roqmeType = metric ? null : oneOf(in, "roqmeType", ROQME_TYPES);
        List<String> literals = "enum".equals(roqmeType) ? literals(in) : List.of();
        String known = metric ? null : identifier(in, "known");
        double initial = metric ? initial(in) : 0.5;
        String ns = in.path("namespace").asText("");
        return new InputSpec(kind, ns, required(in, "name"), roqmeType, literals,
                identifier(in, "param"), type, known, initial);
    }

    private static VariationPoint varpoint(JsonNode vp, String at) {
        Binding binding = within(at + ".binding", () -> binding(vp.get("binding")));
        return within(at, () -> varpoint(vp, binding));
    }

    /** Runs {@code parse}; a problem it finds is reported at {@code at} (a path in the file). */
    private static <T> T within(String at, Supplier<T> parse) {
        try {
            return parse.get();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(at + ": " + e.getMessage(), e);
        }
    }

    private static VariationPoint varpoint(JsonNode vp, Binding binding) {
        String name = identifier(vp, "name");
        List<JsonNode> values = new ArrayList<>();
        vp.path("values").forEach(values::add);
        if (values.isEmpty()) {
            throw new IllegalArgumentException("varpoint " + name + " has no values");
        }
        String kind = required(vp, "kind");
        if (kind.equals("boolean")) {
            // By index the 0 and 1 of the .mzn: nothing else would keep the encoding internal.
            if (!vp.path("values").equals(BOOLEAN_VALUES)) {
                throw new IllegalArgumentException("varpoint " + name + " (boolean) has values " + vp.path("values")
                        + ", not [false,true]");
            }
        } else if (!kind.equals("number") && !kind.equals("enum")) {
            throw new IllegalArgumentException("varpoint " + name + " has kind '" + kind + "' (enum, number or boolean)");
        }
        for (JsonNode v : values) {
            if (kind.equals("number") ? !v.isNumber() : kind.equals("enum") && !v.isTextual()) {
                throw new IllegalArgumentException("varpoint " + name + " (" + kind + ") has value " + v);
            }
        }
        Integer preset = preset(vp);
        if (preset != null && (preset < 0 || preset >= values.size())) {
            throw new IllegalArgumentException("varpoint " + name + " has preset " + preset + " outside its values");
        }
        Integer initial = index(vp, "initial");
        if (initial != null && (initial < 0 || initial >= values.size())) {
            throw new IllegalArgumentException("varpoint " + name + " has initial " + initial + " outside its values");
        }
        return new VariationPoint(name, kind, List.copyOf(values), preset, identifier(vp, "decision"),
                identifier(vp, "input"), identifier(vp, "inputValue"), identifier(vp, "current"), binding, initial);
    }

    /** The binding with the fields applying it needs: {@code variable} (bt, btport), the query's four (arch). */
    private static Binding binding(JsonNode b) {
        if (b == null || b.isNull()) {
            return null;
        }
        String type = oneOf(b, "type", List.of("bt", "arch", "btport"));
        if (type.equals("arch")) {
            for (String field : List.of("parameterSetRepository", "parameterSet", "component", "parameter")) {
                if (b.get(field) == null || !b.get(field).isTextual()) {
                    throw new IllegalArgumentException("missing field '" + field + "' (a string, may be empty)");
                }
            }
        } else {
            required(b, "variable");
        }
        return new Binding(type, b);
    }

    /** A required top-level array ({@code inputs}, {@code varpoints}). */
    private static JsonNode array(JsonNode root, String field) {
        JsonNode n = root.get(field);
        if (n == null || n.isNull()) {
            throw new IllegalArgumentException("missing field '" + field + "' (an array)");
        }
        if (!n.isArray()) {
            throw new IllegalArgumentException("field '" + field + "' is " + n.getNodeType().toString().toLowerCase()
                    + ", not an array");
        }
        return n;
    }

    /** The literals of an enum context: a non-empty array of names. */
    private static List<String> literals(JsonNode in) {
        JsonNode n = in.get("literals");
        if (n == null || !n.isArray() || n.isEmpty()) {
            throw new IllegalArgumentException("missing field 'literals' (an enum context needs a non-empty array)");
        }
        List<String> literals = new ArrayList<>();
        for (JsonNode l : n) {
            if (!l.isTextual() || l.asText().isEmpty()) {
                throw new IllegalArgumentException("field 'literals' has " + l + ", not a name");
            }
            literals.add(l.asText());
        }
        return Collections.unmodifiableList(literals);
    }

    /** A metric's start value: a number in [0,1], 0.5 when absent. */
    private static double initial(JsonNode in) {
        JsonNode n = in.get("initial");
        if (n == null || n.isNull()) {
            return 0.5;
        }
        if (!n.isNumber() || !(n.asDouble() >= 0 && n.asDouble() <= 1)) {
            throw new IllegalArgumentException("field 'initial' is " + n + ", not a number in [0,1]");
        }
        return n.asDouble();
    }

    /** A varpoint's preset: a whole number (range checked by the caller), or null. */
    private static Integer preset(JsonNode vp) {
        return index(vp, "preset");
    }

    /** An optional index field: a whole number (range checked by the caller), or null. */
    private static Integer index(JsonNode vp, String field) {
        JsonNode n = vp.get(field);
        if (n == null || n.isNull()) {
            return null;
        }
        double d = n.asDouble();
        if (!n.isNumber() || d != Math.rint(d) || Math.abs(d) > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("field '" + field + "' is " + n + ", not a 0-based index into 'values'");
        }
        return (int) d;
    }

    /** A required text field that must be one of {@code allowed}. */
    private static String oneOf(JsonNode node, String field, List<String> allowed) {
        String value = required(node, field);
        if (!allowed.contains(value)) {
            String last = allowed.get(allowed.size() - 1);
            String expected = allowed.size() == 1 ? last
                    : String.join(", ", allowed.subList(0, allowed.size() - 1)) + " or " + last;
            throw new IllegalArgumentException("field '" + field + "' is '" + value + "', expected " + expected);
        }
        return value;
    }

    /** A required MiniZinc parameter or variable name. */
    private static String identifier(JsonNode node, String field) {
        String value = required(node, field);
        if (!IDENTIFIER.matcher(value).matches()) {
            throw new IllegalArgumentException("field '" + field + "' is '" + value
                    + "', not a MiniZinc identifier ([A-Za-z][A-Za-z0-9_]*)");
        }
        return value;
    }

    public Optional<VariationPoint> varpoint(String name) {
        return varpoints.stream().filter(v -> v.name().equals(name)).findFirst();
    }

    private static String required(JsonNode node, String field) {
        JsonNode n = node.get(field);
        if (n == null || n.isNull() || n.asText().isEmpty()) {
            throw new IllegalArgumentException("missing field '" + field + "'");
        }
        return n.asText();
    }

    private static String optional(JsonNode node, String field) {
        JsonNode n = node.get(field);
        return n == null || n.isNull() ? null : n.asText();
    }
}
