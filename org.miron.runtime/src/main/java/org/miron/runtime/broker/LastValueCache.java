package org.miron.runtime.broker;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.miron.runtime.Json;

/**
 * Latest message per topic and subject. Several subjects share one topic ({@code roqme.estimate}
 * carries every property, {@code roqme.context} every context), so the key is the topic plus the
 * body's {@code namespace}/{@code name} when the body is a JSON object with a {@code name};
 * otherwise the topic alone. A late subscriber thus gets the latest estimate of each property,
 * not only of the last one published. Topics are kept as ISO-8859-1 strings so prefix matching
 * is byte-wise, exactly like ZeroMQ subscription matching. Bounded: the least recently updated
 * entry is evicted beyond {@code maxTopics}. Only valid messages are cached ({@link CacheAdmission}):
 * an invalid one never replaces the last valid value of its key.
 */
public final class LastValueCache {
    private final int maxTopics;
    private final LinkedHashMap<String, List<byte[]>> last;
    private long version; // bumped by every cached message: tells a snapshot writer something changed

    public LastValueCache(int maxTopics) {
        this.maxTopics = maxTopics;
        this.last = new LinkedHashMap<>(16, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, List<byte[]>> eldest) {
                return size() > LastValueCache.this.maxTopics;
            }
        };
    }

    /** Remembers a valid message (frame 0 is the topic); false when it was refused. */
    public synchronized boolean put(List<byte[]> frames) {
        if (frames.isEmpty() || CacheAdmission.reject(frames) != null) {
            return false;
        }
        String key = new String(frames.get(0), StandardCharsets.ISO_8859_1) + subject(frames);
        last.remove(key); // re-insert so eviction and replay order follow updates
        last.put(key, List.copyOf(frames));
        version++;
        return true;
    }

    /** "\0namespace\0name" for bodies naming a subject, "" otherwise. */
    private static String subject(List<byte[]> frames) {
        if (frames.size() < 2 || frames.get(1).length == 0 || frames.get(1)[0] != '{') {
            return "";
        }
        try {
            JsonNode body = Json.MAPPER.readTree(frames.get(1));
            JsonNode name = body.get("name");
            if (name == null || !name.isTextual()) {
                return "";
            }
            return "\0" + body.path("namespace").asText("") + "\0" + name.asText();
        } catch (IOException | RuntimeException e) {
            return ""; // not JSON: cached by topic only
        }
    }

    /** Latest messages whose topic starts with the (byte) prefix, oldest update first. */
    public List<List<byte[]>> matching(byte[] prefix) {
        String p = new String(prefix, StandardCharsets.ISO_8859_1);
        return matching(topic -> new String(topic, StandardCharsets.ISO_8859_1).startsWith(p));
    }

    /** Latest messages whose topic passes the test, oldest update first (each once). */
    public synchronized List<List<byte[]>> matching(Predicate<byte[]> topic) {
        List<List<byte[]>> out = new ArrayList<>();
        for (List<byte[]> frames : last.values()) {
            if (topic.test(frames.get(0))) {
                out.add(frames);
            }
        }
        return out;
    }

    public synchronized long version() {
        return version;
    }

    public synchronized int size() {
        return last.size();
    }
}
