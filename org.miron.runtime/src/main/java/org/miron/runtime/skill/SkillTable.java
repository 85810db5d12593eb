package org.miron.runtime.skill;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.miron.runtime.Json;

/**
 * How the mock simulates skills: name → duration and outcome. File format (JSON object):
 * <pre>
 * { "GoTo":  {"duration": 1500, "result": "SUCCESS", "result-value": "arrived", "outputs": {}},
 *   "Dock":  {"duration": 800,  "result": "ERROR"},
 *   "*":     {"duration": 200,  "result": "SUCCESS"} }
 * </pre>
 * {@code "*"} is used for any skill not listed; without it, unknown skills succeed after 200 ms.
 */
public final class SkillTable {
    /** @param result SUCCESS, ERROR or ABORT */
    public record Entry(long durationMs, String result, JsonNode resultValue, JsonNode outputs) {
    }

    private static final Entry DEFAULT = new Entry(200, "SUCCESS", NullNode.getInstance(), Json.object());
    private final Map<String, Entry> entries;

    public SkillTable(Map<String, Entry> entries) {
        this.entries = Map.copyOf(entries);
    }

    public static SkillTable defaults() {
        return new SkillTable(Map.of());
    }

    public static SkillTable load(Path file) throws IOException {
        JsonNode root = Json.MAPPER.readTree(file.toFile());
        if (root == null || !root.isObject()) {
            throw new IOException(file + ": skill table must be a JSON object name -> {duration, result}");
        }
        Map<String, Entry> map = new LinkedHashMap<>();
        var it = root.fields();
        while (it.hasNext()) {
            var e = it.next();
            JsonNode n = e.getValue();
            String result = n.path("result").asText("SUCCESS");
            if (!result.equals("SUCCESS") && !result.equals("ERROR") && !result.equals("ABORT")) {
                throw new IOException(file + ": skill " + e.getKey() + " has result " + result
                        + " (SUCCESS, ERROR or ABORT)");
            }
            map.put(e.getKey(), new Entry(n.path("duration").asLong(DEFAULT.durationMs()), result,
                    n.has("result-value") ? n.get("result-value") : NullNode.getInstance(),
                    n.has("outputs") ? n.get("outputs") : Json.object()));
        }
        return new SkillTable(map);
    }

    public Entry lookup(String skill) {
        Entry e = entries.get(skill);
        if (e == null) {
            e = entries.getOrDefault("*", DEFAULT);
        }
        return e;
    }
}
