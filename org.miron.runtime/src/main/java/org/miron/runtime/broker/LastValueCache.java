package org.miron.runtime.broker;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Latest message per topic. Topics are kept as ISO-8859-1 strings so that prefix matching is
 * byte-wise, exactly like ZeroMQ subscription matching. Bounded: the least recently updated
 * topic is evicted beyond {@code maxTopics}.
 */
public final class LastValueCache {
    private final int maxTopics;
    private final LinkedHashMap<String, List<byte[]>> last;

    public LastValueCache(int maxTopics) {
        this.maxTopics = maxTopics;
        this.last = new LinkedHashMap<>(16, 0.75f, false) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, List<byte[]>> eldest) {
                return size() > LastValueCache.this.maxTopics;
            }
        };
    }

    /** Remembers a message; frame 0 is the topic. */
    public synchronized void put(List<byte[]> frames) {
        if (frames.isEmpty()) {
            return;
        }
        String topic = new String(frames.get(0), StandardCharsets.ISO_8859_1);
        last.remove(topic); // re-insert so eviction order follows updates
        last.put(topic, List.copyOf(frames));
    }

    /** Latest messages whose topic starts with the (byte) prefix, oldest update first. */
    public synchronized List<List<byte[]>> matching(byte[] prefix) {
        String p = new String(prefix, StandardCharsets.ISO_8859_1);
        List<List<byte[]>> out = new ArrayList<>();
        for (Map.Entry<String, List<byte[]>> e : last.entrySet()) {
            if (e.getKey().startsWith(p)) {
                out.add(e.getValue());
            }
        }
        return out;
    }

    public synchronized int size() {
        return last.size();
    }
}
