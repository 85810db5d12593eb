package org.miron.runtime.executor;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Key/value store shared by the nodes of one (sub)tree, as BehaviorTree.CPP's Blackboard. A
 * subtree's blackboard may remap some of its keys to keys of its parent's blackboard: reading or
 * writing a remapped key goes to the parent. Thread-safe, so monitors may read it while it runs.
 */
public final class Blackboard {
    private final Blackboard parent;
    private final Map<String, String> remapping = new ConcurrentHashMap<>();
    private final Map<String, Object> storage = new ConcurrentHashMap<>();

    private Blackboard(Blackboard parent) {
        this.parent = parent;
    }

    public static Blackboard create() {
        return new Blackboard(null);
    }

    /** A blackboard for a subtree: isolated until keys are remapped to this one. */
    public Blackboard createChild() {
        return new Blackboard(this);
    }

    /** Makes {@code internalKey} an alias of {@code parentKey} in the parent blackboard. */
    public void remap(String internalKey, String parentKey) {
        if (parent == null) {
            throw new IllegalStateException("a root blackboard has no parent to remap '" + internalKey + "' to");
        }
        remapping.put(internalKey, parentKey);
    }

    public Optional<Object> get(String key) {
        String parentKey = remapping.get(key);
        if (parentKey != null) {
            return parent.get(parentKey);
        }
        return Optional.ofNullable(storage.get(key));
    }

    /** Writes a value (null removes the entry), to the parent when the key is remapped. */
    public void set(String key, Object value) {
        String parentKey = remapping.get(key);
        if (parentKey != null) {
            parent.set(parentKey, value);
        } else if (value == null) {
            storage.remove(key);
        } else {
            storage.put(key, value);
        }
    }

    /** Keys stored here (not the remapped ones), sorted. */
    public Set<String> localKeys() {
        return new TreeSet<>(storage.keySet());
    }

    public Map<String, String> remappings() {
        return Map.copyOf(remapping);
    }

    @Override
    public String toString() {
        return "Blackboard" + new java.util.TreeMap<>(storage) + (remapping.isEmpty() ? "" : " remapped " + remapping);
    }
}
