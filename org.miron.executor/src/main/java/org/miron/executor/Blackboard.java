package org.miron.executor;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Key/value store shared by the nodes of one (sub)tree, as BehaviorTree.CPP's Blackboard. A
 * subtree's blackboard may remap some of its keys to keys of its parent's blackboard: reading or
 * writing a remapped key goes to the parent. Version 4 adds automatic remapping (a key not found
 * here, and not starting with '_', is the parent's), {@code @key} for the root blackboard's entry,
 * and entries that exist without a value yet ({@link #declare}). Thread-safe, so monitors may read
 * it while it runs.
 */
public final class Blackboard {
    /** The value of an entry that exists but was never written (ConcurrentHashMap holds no null). */
    private static final Object NO_VALUE = new Object() {
        @Override
        public String toString() {
            return "<no value>";
        }
    };

    private final Blackboard parent;
    private final Map<String, String> remapping = new ConcurrentHashMap<>();
    /** Who made each remapping, e.g. {@code Main/travel: goal="{ward}"}, for error messages. */
    private final Map<String, String> remappedBy = new ConcurrentHashMap<>();
    private final Map<String, Object> storage = new ConcurrentHashMap<>();
    /** How many times each entry stored here was written (BT.CPP 4's sequence_id). */
    private final Map<String, Long> writes = new ConcurrentHashMap<>();
    private volatile boolean autoRemap;

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

    /** As {@link #remap(String, String)}, saying who made the remapping (named when the key is missing). */
    public void remap(String internalKey, String parentKey, String madeBy) {
        remap(internalKey, parentKey);
        remappedBy.put(internalKey, madeBy);
    }

    /**
     * Where an entry without a value was expected to come from, for an error message: the chain of
     * remappings it follows up to the key nothing has written, e.g. {@code 'goal' is 'ward' of the
     * parent tree (remapped by Main/travel: goal="{ward}"), which nothing has written}.
     */
    public String whereFrom(String key) {
        StringBuilder text = new StringBuilder();
        Blackboard board = this;
        String current = key;
        while (true) {
            if (current.startsWith("@")) {
                current = current.substring(1);
                board = root();
                text.append(" of the root tree");
            }
            if (board.storage.containsKey(current)) {
                break;
            }
            String parentKey = board.remapping.get(current);
            if (parentKey != null) {
                String by = board.remappedBy.get(current);
                text.append(text.length() == 0 ? "" : ",").append(" remapped").append(by == null ? "" : " by " + by)
                        .append(" to the parent's '").append(parentKey).append("'");
            } else if (board.autoRemap && !current.startsWith("_")) {
                parentKey = current;
                text.append(text.length() == 0 ? "" : ",").append(" auto-remapped to the parent's '").append(current)
                        .append("'");
            } else {
                break;
            }
            board = board.parent;
            current = parentKey;
        }
        return text.append(text.length() == 0 ? "" : ",").append(" nothing has written ")
                .append(current.equals(key) ? "it" : "'" + current + "'").toString().trim();
    }

    /** Version 4's _autoremap: every key not found here and not starting with '_' is the parent's. */
    public void setAutoRemap(boolean autoRemap) {
        if (parent == null && autoRemap) {
            throw new IllegalStateException("a root blackboard has no parent to remap to");
        }
        this.autoRemap = autoRemap;
    }

    public Optional<Object> get(String key) {
        Object value = entry(key);
        return value == null || value == NO_VALUE ? Optional.empty() : Optional.of(value);
    }

    /** Whether the entry exists, with or without a value (BT.CPP 4's getEntry). */
    public boolean contains(String key) {
        return entry(key) != null;
    }

    private Object entry(String key) {
        if (key.startsWith("@")) {
            return root().entry(key.substring(1));
        }
        Object value = storage.get(key);
        if (value != null) {
            return value;
        }
        String parentKey = remapping.get(key);
        if (parentKey != null) {
            return parent.entry(parentKey);
        }
        if (autoRemap && !key.startsWith("_")) {
            return parent.entry(key);
        }
        return null;
    }

    /** Writes a value (null removes the entry), to the parent when the key is remapped. */
    public void set(String key, Object value) {
        owner(key).store(local(key), value);
    }

    /** Creates the entry without a value if it does not exist (BT.CPP 4 does it for every {key} port). */
    public void declare(String key) {
        Blackboard owner = owner(key);
        String local = local(key);
        if (owner.storage.putIfAbsent(local, NO_VALUE) == null) {
            owner.writes.put(local, 0L);
        }
    }

    /**
     * How many times the entry was written, -1 when it does not exist: a node can tell whether it
     * changed since it last looked (WasEntryUpdated, SkipUnlessUpdated, WaitValueUpdate).
     */
    public long writeCount(String key) {
        if (!contains(key)) {
            return -1;
        }
        return owner(key).writes.getOrDefault(local(key), 0L);
    }

    private void store(String key, Object value) {
        if (value == null) {
            storage.remove(key);
            writes.remove(key);
        } else {
            storage.put(key, value);
            writes.merge(key, 1L, Long::sum);
        }
    }

    /** The blackboard that holds (or would create) the entry, as BT.CPP 4's createEntryImpl. */
    private Blackboard owner(String key) {
        if (key.startsWith("@")) {
            return root();
        }
        if (storage.containsKey(key)) {
            return this;
        }
        String parentKey = remapping.get(key);
        if (parentKey != null) {
            return parent.owner(parentKey);
        }
        if (autoRemap && !key.startsWith("_")) {
            return parent.owner(key);
        }
        return this;
    }

    /** The key as stored in {@link #owner(String)}. */
    private String local(String key) {
        if (key.startsWith("@")) {
            return key.substring(1);
        }
        if (storage.containsKey(key)) {
            return key;
        }
        String parentKey = remapping.get(key);
        if (parentKey != null) {
            return parent.local(parentKey);
        }
        if (autoRemap && !key.startsWith("_")) {
            return parent.local(key);
        }
        return key;
    }

    private Blackboard root() {
        Blackboard board = this;
        while (board.parent != null) {
            board = board.parent;
        }
        return board;
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
        return "Blackboard" + new TreeMap<>(storage) + (remapping.isEmpty() ? "" : " remapped " + remapping);
    }
}
