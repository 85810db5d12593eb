package org.miron.runtime.recording;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.miron.runtime.Json;

/**
 * Reads a {@link BusLog}. Its last line may be cut short (a killed process): it is left out. Any
 * other line that is not a bus event, or a first line that is not the header, is refused with its
 * number.
 */
public final class BusLogReader {
    /** One message of the bus: when (microseconds since the epoch), its topic, its body. */
    public record BusEvent(long timeUs, String topic, JsonNode message) {
    }

    private BusLogReader() {
    }

    public static List<BusEvent> read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        boolean endsComplete = Files.size(file) == 0 || endsWithNewline(file);
        if (lines.isEmpty()) {
            throw new BtlogFormatException(file + ": empty, not a bus log");
        }
        JsonNode header = parse(lines.get(0));
        if (header == null || !BusLog.FORMAT.equals(header.path("format").asText())) {
            throw new BtlogFormatException(file + ": not a bus log (its first line is not {\"format\":\"" + BusLog.FORMAT + "\",...})");
        }
        if (header.path("version").asInt() != BusLog.VERSION) {
            throw new BtlogFormatException(file + ": bus log version " + header.path("version") + ", only " + BusLog.VERSION + " is known");
        }
        List<BusEvent> events = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank()) {
                continue;
            }
            JsonNode json = parse(line);
            boolean valid = json != null && json.path("timeUs").isIntegralNumber() && json.path("topic").isTextual()
                    && json.path("message").isObject();
            if (!valid) {
                if (i == lines.size() - 1 && !endsComplete) {
                    break; // the line being written when the process stopped
                }
                throw new BtlogFormatException(file + ":" + (i + 1) + ": not a bus event {\"timeUs\",\"topic\",\"message\"}");
            }
            events.add(new BusEvent(json.get("timeUs").asLong(), json.get("topic").asText(), json.get("message")));
        }
        return events;
    }

    private static boolean endsWithNewline(Path file) throws IOException {
        try (var channel = java.nio.channels.FileChannel.open(file)) {
            java.nio.ByteBuffer last = java.nio.ByteBuffer.allocate(1);
            channel.read(last, channel.size() - 1);
            return last.get(0) == '\n';
        }
    }

    private static JsonNode parse(String line) {
        try {
            JsonNode json = Json.MAPPER.readTree(line);
            return json != null && json.isObject() ? json : null;
        } catch (IOException e) {
            return null;
        }
    }
}
