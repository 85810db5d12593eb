package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Runs the real minizinc (Gecode) on a generated model as the engine does (docs/io-json.md):
 * every parameter from name.io.json with its neutral value (metrics at their initial value,
 * contexts unknown, no override, no current value), overridden by the test's own values.
 */
final class MiniZinc {
    static final ObjectMapper JSON = new ObjectMapper();

    final Path dir;
    final JsonNode io;

    MiniZinc(Path ioJson) {
        try {
            this.dir = ioJson.getParent();
            this.io = JSON.readTree(ioJson.toFile());
        } catch (IOException e) {
            throw new AssertionError("cannot read " + ioJson + ": " + e);
        }
    }

    /** The data the engine would feed before anything is observed. */
    ObjectNode defaults() {
        ObjectNode data = JSON.createObjectNode();
        for (JsonNode in : io.get("inputs")) {
            String param = in.get("param").asText();
            switch (in.get("type").asText()) {
            case "float" -> data.put(param, in.has("initial") ? in.get("initial").asDouble() : 0.0);
            case "bool" -> data.put(param, false);
            default -> data.put(param, 0);
            }
            if (in.has("known")) {
                data.put(in.get("known").asText(), false);
            }
        }
        for (JsonNode vp : io.get("varpoints")) {
            data.put(vp.get("input").asText(), false);
            data.put(vp.get("inputValue").asText(), 0);
            data.put(vp.get("current").asText(), -1);
        }
        for (JsonNode rule : io.path("rules")) {
            data.put(rule.get("keep").asText(), true); // every rule kept, as the engine's first solve
        }
        return data;
    }

    /** Index of a value in a varpoint's table (label or number). */
    int index(String varpoint, String value) {
        JsonNode values = varpoint(varpoint).get("values");
        for (int i = 0; i < values.size(); i++) {
            if (values.get(i).asText().equals(value) || (values.get(i).isNumber()
                    && Double.parseDouble(value) == values.get(i).asDouble())) {
                return i;
            }
        }
        throw new AssertionError(varpoint + " has no value " + value);
    }

    JsonNode varpoint(String name) {
        for (JsonNode vp : io.get("varpoints")) {
            if (vp.get("name").asText().equals(name)) {
                return vp;
            }
        }
        throw new AssertionError("no varpoint " + name);
    }

    /** The value (label or number as text) a decision selects. */
    String value(String varpoint, Map<String, Integer> decisions) {
        return varpoint(varpoint).get("values").get(decisions.get(varpoint + "_var")).asText();
    }

    /** Solves with the given data; fails on errors and on unsatisfiable models. */
    Map<String, Integer> solve(ObjectNode data) {
        List<String> command = new ArrayList<>(List.of("minizinc", "--solver", "gecode", "--output-mode", "json",
                "--time-limit", "20000", "-d", io.get("dzn").asText(), "--cmdline-json-data", data.toString(),
                io.get("mzn").asText()));
        try {
            Process process = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(false).start();
            byte[] stdout = process.getInputStream().readAllBytes();
            byte[] stderr = process.getErrorStream().readAllBytes();
            if (!process.waitFor(60, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                fail("minizinc did not finish");
            }
            String text = new String(stdout, StandardCharsets.UTF_8);
            assertEquals("minizinc failed: " + new String(stderr, StandardCharsets.UTF_8) + text, 0, process.exitValue());
            assertTrue("no solution (" + text + ") for " + data, text.contains("----------"));
            // With solve maximize, the last solution printed is the best one.
            String last = "";
            for (String chunk : text.split("----------")) {
                if (!chunk.isBlank() && !chunk.trim().startsWith("==========")) {
                    last = chunk.trim();
                }
            }
            JsonNode solution = JSON.readTree(last);
            Map<String, Integer> result = new LinkedHashMap<>();
            solution.fields().forEachRemaining(e -> result.put(e.getKey(), e.getValue().asInt()));
            return result;
        } catch (IOException e) {
            throw new AssertionError("cannot run minizinc (is it installed?): " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
    }
}
