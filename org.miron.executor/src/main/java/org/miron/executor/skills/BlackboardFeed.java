package org.miron.executor.skills;

import java.util.HashMap;
import java.util.Map;
import java.util.Objects;
import org.miron.executor.Blackboard;

/**
 * Copies numeric decisions ({@code miron.blackboard.<vp>}) into a blackboard under the varpoint's
 * name, where the woven tree reads them as {@code {vp}}. Applied by the tree before each tick, on
 * the ticking thread, and only for values that changed, so the tree may overwrite a key meanwhile.
 */
public final class BlackboardFeed {
    private final VariantSource source;
    private final Map<String, Object> applied = new HashMap<>();

    public BlackboardFeed(VariantSource source) {
        this.source = Objects.requireNonNull(source);
    }

    public void applyTo(Blackboard blackboard) {
        source.snapshot().forEach((key, value) -> {
            if (!value.equals(applied.get(key))) {
                blackboard.set(key, value);
                applied.put(key, value);
            }
        });
    }
}
