package org.miron.executor.skills;

import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Latest value per variation point, written by whoever receives the decisions (the bus subscriber
 * on {@code miron.variant.<vp>} or {@code miron.blackboard.<vp>}) and read by the ticking thread.
 * Only the latest value matters, so a plain concurrent map is enough: no queue, no backlog.
 */
public final class VariantSource {
    private final Map<String, Object> values = new ConcurrentHashMap<>();

    /** Records a new decision for {@code varpoint} (null forgets it). Safe from any thread. */
    public void publish(String varpoint, Object value) {
        if (value == null) {
            values.remove(varpoint);
        } else {
            values.put(varpoint, value);
        }
    }

    public Optional<Object> current(String varpoint) {
        return Optional.ofNullable(values.get(varpoint));
    }

    /** All current values, sorted by varpoint. */
    public Map<String, Object> snapshot() {
        return new TreeMap<>(values);
    }
}
