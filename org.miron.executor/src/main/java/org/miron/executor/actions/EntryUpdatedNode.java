package org.miron.executor.actions;

import static org.miron.bt.nodes.BuiltinNodes.ENTRY;

import org.miron.executor.BtBuildException;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;

/**
 * WasEntryUpdated(entry) (BT.CPP 4): SUCCESS when the blackboard entry was written since this node
 * last looked, FAILURE when not (or when it does not exist). {@code entry} names the key, with or
 * without braces.
 */
public final class EntryUpdatedNode extends Node {
    private final String key;
    private long seen;

    public EntryUpdatedNode(NodeInfo info) {
        super(info);
        this.key = entryKey(info);
    }

    /** The key an entry port names: {key} or the plain key. */
    public static String entryKey(NodeInfo info) {
        String raw = info.ports().raw(ENTRY);
        if (raw == null || raw.isEmpty()) {
            throw new BtBuildException(info.path() + ": missing parameter entry");
        }
        return Ports.blackboardKey(ENTRY, raw).orElse(raw);
    }

    @Override
    protected NodeStatus tick() {
        long writes = ports().blackboard().writeCount(key);
        if (writes < 0) {
            return NodeStatus.FAILURE;
        }
        boolean updated = writes != seen;
        seen = writes;
        return updated ? NodeStatus.SUCCESS : NodeStatus.FAILURE;
    }
}
