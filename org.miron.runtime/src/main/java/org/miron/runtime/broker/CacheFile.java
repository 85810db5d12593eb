package org.miron.runtime.broker;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

/**
 * Snapshot of the last-value cache in a file ({@code broker --cache-file FILE}), so a restarted
 * broker replays the state it had even for publishers that will not speak again. Written at most
 * every {@link #INTERVAL_MS} when the cache changed, atomically (temporary file, then rename), so
 * a kill -9 leaves the previous snapshot, never half a file. Format: a JSON array of entries in
 * update order, each an array of base64 frames (topic, body). Loaded entries pass the cache's
 * validation again; the broker's own topics are not restored (a new run has a new epoch).
 */
final class CacheFile {
    static final long INTERVAL_MS = 500;
    private static final Logger LOG = Logger.getLogger(CacheFile.class.getName());
    private final Path file;
    private final LastValueCache cache;
    private long savedVersion = -1;

    CacheFile(Path file, LastValueCache cache) {
        this.file = file;
        this.cache = cache;
    }

    /** Restores the snapshot if there is one; a broken file is a start-up error. Returns the entries restored. */
    int load() throws IOException {
        if (!Files.exists(file)) {
            return 0;
        }
        JsonNode root = Json.MAPPER.readTree(file.toFile());
        if (root == null || !root.isArray()) {
            throw new IOException(file + ": not a cache snapshot (a JSON array)");
        }
        int restored = 0;
        for (JsonNode entry : root) {
            List<byte[]> frames = new ArrayList<>();
            for (JsonNode f : entry) {
                frames.add(Base64.getDecoder().decode(f.asText()));
            }
            if (!frames.isEmpty() && !new String(frames.get(0), StandardCharsets.ISO_8859_1).startsWith(Topics.BROKER_PREFIX)
                    && cache.put(frames)) {
                restored++;
            }
        }
        savedVersion = cache.version();
        return restored;
    }

    /** Writes the snapshot if the cache changed since the last one. */
    void saveIfChanged() {
        long version = cache.version();
        if (version == savedVersion) {
            return;
        }
        ArrayNode root = Json.MAPPER.createArrayNode();
        for (List<byte[]> frames : cache.matching(new byte[0])) {
            ArrayNode entry = root.addArray();
            frames.forEach(f -> entry.add(Base64.getEncoder().encodeToString(f)));
        }
        try {
            Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
            Files.writeString(tmp, Json.write(root));
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            savedVersion = version;
        } catch (IOException e) {
            LOG.warning("broker: cannot write the cache snapshot " + file + ": " + e.getMessage());
        }
    }
}
