package org.miron.runtime.roqme;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.Json;
import org.miron.runtime.roqme.reasoner.Reasoner;

/**
 * {@code miron roqme run --state FILE}: the live evidence kept across restarts, as JSON
 * {@code {"format":1,"model","time","beliefs":{id:[{"r","survivalMs","ageMs"}]}}}, written atomically
 * (a temporary file moved over the old one). On start the pieces are restored aged by the time the
 * provider was down. An unreadable file is a start-up error; a missing one is a first run.
 */
public final class EvidenceState {
    /** What a state file holds. */
    public record Saved(String model, long time, Map<String, List<Reasoner.Piece>> beliefs) {
    }

    private EvidenceState() {
    }

    public static void write(Path file, String model, long time, Map<String, List<Reasoner.Piece>> evidence) throws IOException {
        ObjectNode o = Json.object();
        o.put("format", 1);
        o.put("model", model);
        o.put("time", time);
        ObjectNode beliefs = o.putObject("beliefs");
        evidence.forEach((id, pieces) -> {
            ArrayNode a = beliefs.putArray(id);
            for (Reasoner.Piece p : pieces) {
                a.addObject().put("r", p.r()).put("survivalMs", p.survivalMs()).put("ageMs", p.ageMs());
            }
        });
        Path dir = file.toAbsolutePath().getParent();
        Path tmp = Files.createTempFile(dir, file.getFileName().toString(), ".tmp");
        try {
            Files.writeString(tmp, Json.write(o));
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** The saved state, or null when the file does not exist. */
    public static Saved read(Path file) throws IOException {
        if (!Files.exists(file)) {
            return null;
        }
        JsonNode o;
        try {
            o = Json.MAPPER.readTree(Files.readString(file));
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IOException(file + ": not a provider state file: " + e.getOriginalMessage(), e);
        }
        if (o == null || o.path("format").asInt() != 1 || !o.path("time").isNumber() || !o.path("beliefs").isObject()) {
            throw new IOException(file + ": not a provider state file (format 1 with time and beliefs)");
        }
        Map<String, List<Reasoner.Piece>> beliefs = new LinkedHashMap<>();
        var fields = o.get("beliefs").fields();
        while (fields.hasNext()) {
            var e = fields.next();
            List<Reasoner.Piece> pieces = new ArrayList<>();
            for (JsonNode p : e.getValue()) {
                double r = p.path("r").asDouble(Double.NaN);
                long survival = p.path("survivalMs").asLong(0);
                if (!(r > 0) || Double.isInfinite(r) || survival <= 0 || !p.path("ageMs").isNumber()) {
                    throw new IOException(file + ": bad evidence of " + e.getKey() + ": " + p);
                }
                pieces.add(new Reasoner.Piece(r, survival, p.get("ageMs").asLong()));
            }
            beliefs.put(e.getKey(), pieces);
        }
        return new Saved(o.path("model").asText(""), o.get("time").asLong(), beliefs);
    }
}
