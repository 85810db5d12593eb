package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Optional;
import java.util.TreeSet;
import org.miron.executor.Blackboard;

/**
 * The BLACKBOARD reply: for each subtree named in the request ({@code name;name...}, names as
 * {@link GrootTree.Subtree#name()}), its blackboard's own entries as JSON, MessagePack-encoded.
 * As the library: unknown names are left out, nothing found is JSON null, an empty blackboard is
 * null, an entry without a value is null, keys in order (nlohmann::json's objects are sorted).
 */
public final class BlackboardDump {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private BlackboardDump() {
    }

    public static byte[] reply(GrootTree tree, String names) {
        ObjectNode dump = null;
        for (String name : names.split(";", -1)) {
            for (GrootTree.Subtree subtree : tree.subtrees()) {
                if (subtree.name().equals(name)) {
                    if (dump == null) {
                        dump = JSON.objectNode();
                    }
                    dump.set(name, entries(subtree.blackboard()));
                    break;
                }
            }
        }
        return MsgPack.encode(dump == null ? NullNode.getInstance() : sorted(dump));
    }

    private static JsonNode entries(Blackboard blackboard) {
        TreeSet<String> keys = new TreeSet<>(blackboard.localKeys());
        if (keys.isEmpty()) {
            return NullNode.getInstance();
        }
        ObjectNode entries = JSON.objectNode();
        for (String key : keys) {
            entries.set(key, value(blackboard.get(key)));
        }
        return entries;
    }

    private static JsonNode value(Optional<Object> value) {
        if (value.isEmpty()) {
            return NullNode.getInstance();
        }
        Object v = value.get();
        if (v instanceof Boolean b) {
            return JSON.booleanNode(b);
        }
        if (v instanceof Integer || v instanceof Long || v instanceof Short || v instanceof Byte) {
            return JSON.numberNode(((Number) v).longValue());
        }
        if (v instanceof Number n) {
            return JSON.numberNode(n.doubleValue());
        }
        return JSON.textNode(String.valueOf(v));
    }

    private static ObjectNode sorted(ObjectNode object) {
        TreeSet<String> names = new TreeSet<>();
        object.fieldNames().forEachRemaining(names::add);
        ObjectNode out = JSON.objectNode();
        names.forEach(k -> out.set(k, object.get(k)));
        return out;
    }
}
