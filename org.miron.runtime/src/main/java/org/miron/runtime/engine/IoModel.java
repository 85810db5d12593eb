package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import org.miron.runtime.Json;

/** The generated {@code name.io.json} (docs/io-json.md), with the .mzn/.dzn paths resolved. */
public record IoModel(String model, Path mzn, Path dzn, List<InputSpec> inputs, List<VarPoint> varpoints) {

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
        for (JsonNode in : root.path("inputs")) {
            inputs.add(input(in));
        }
        List<VarPoint> vps = new ArrayList<>();
        for (JsonNode vp : root.path("varpoints")) {
            vps.add(varpoint(vp));
        }
        String model = optional(root, "model");
        return new IoModel(model == null ? "model" : model, mzn, dzn, List.copyOf(inputs), List.copyOf(vps));
    }

    private static InputSpec input(JsonNode in) {
        String kind = required(in, "kind");
        if (!kind.equals("metric") && !kind.equals("context")) {
            throw new IllegalArgumentException("input kind '" + kind + "' is neither metric nor context");
        }
        String type = required(in, "type");
        if (!List.of("float", "bool", "int").contains(type)) {
            throw new IllegalArgumentException("input " + in.path("name").asText() + " has type " + type);
        }
        List<String> literals = new ArrayList<>();
        in.path("literals").forEach(l -> literals.add(l.asText()));
        String roqmeType = kind.equals("context") ? required(in, "roqmeType") : null;
        String known = kind.equals("context") ? required(in, "known") : null;
        double initial = in.hasNonNull("initial") ? in.get("initial").asDouble() : 0.5;
        String ns = in.path("namespace").asText("");
        return new InputSpec(kind, ns, required(in, "name"), roqmeType, Collections.unmodifiableList(literals),
                required(in, "param"), type, known, initial);
    }

    private static VarPoint varpoint(JsonNode vp) {
        String name = required(vp, "name");
        List<JsonNode> values = new ArrayList<>();
        vp.path("values").forEach(values::add);
        if (values.isEmpty()) {
            throw new IllegalArgumentException("varpoint " + name + " has no values");
        }
        String kind = required(vp, "kind");
        boolean numeric = kind.equals("number");
        if (!numeric && !kind.equals("enum")) {
            throw new IllegalArgumentException("varpoint " + name + " has kind '" + kind + "' (enum or number)");
        }
        for (JsonNode v : values) {
            if (numeric ? !v.isNumber() : !v.isTextual()) {
                throw new IllegalArgumentException("varpoint " + name + " (" + kind + ") has value " + v);
            }
        }
        Integer preset = vp.hasNonNull("preset") ? vp.get("preset").asInt() : null;
        if (preset != null && (preset < 0 || preset >= values.size())) {
            throw new IllegalArgumentException("varpoint " + name + " has preset " + preset + " outside its values");
        }
        JsonNode b = vp.get("binding");
        Binding binding = b == null || b.isNull() ? null : new Binding(required(b, "type"), b);
        return new VarPoint(name, kind, List.copyOf(values), preset, required(vp, "decision"),
                required(vp, "input"), required(vp, "inputValue"), required(vp, "current"), binding);
    }

    public Optional<VarPoint> varpoint(String name) {
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
