package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.executor.NodeStatus;

/**
 * One hook Groot2 put on a node (BT.CPP's Monitor::Hook): a BREAKPOINT waits for Groot2, a REPLACE
 * returns {@code desiredStatus} at once; {@code once} removes it after use. Its fields are guarded
 * by the hook itself, on which a paused tick thread waits.
 */
final class GrootHook {
    static final int BREAKPOINT = 0;
    static final int REPLACE = 1;
    static final int PRE = 0;
    static final int POST = 1;

    final int uid;
    boolean enabled = true;
    int mode = BREAKPOINT;
    int position = PRE;
    boolean once;
    NodeStatus desiredStatus = NodeStatus.SKIPPED;
    /** Set by an unlock, taken by the waiting tick. */
    boolean ready;

    GrootHook(int uid) {
        this.uid = uid;
    }

    /** Reads every field from a hook's JSON, as the library's from_json (all required). */
    synchronized void update(HookJson json) {
        enabled = json.enabled();
        once = json.once();
        mode = json.mode();
        position = json.position();
        desiredStatus = json.desiredStatus();
    }

    /** The hook as HOOKS_DUMP lists it (keys in nlohmann::json's sorted order). */
    synchronized JsonNode toJson() {
        ObjectNode json = JsonNodeFactory.instance.objectNode();
        json.put("desired_status", desiredStatus.name());
        json.put("enabled", enabled);
        json.put("mode", mode);
        json.put("once", once);
        json.put("position", position);
        json.put("uid", uid);
        return json;
    }

    /** A hook's JSON, checked: every field the library reads, of its type. */
    record HookJson(int uid, boolean enabled, boolean once, int mode, int position, NodeStatus desiredStatus) {
        static HookJson parse(JsonNode json) {
            if (json == null || !json.isObject()) {
                throw new IllegalArgumentException("a hook is a JSON object");
            }
            return new HookJson(GrootHook.uid(json, "uid"), bool(json, "enabled"), bool(json, "once"), integer(json, "mode"),
                    integer(json, "position"), status(text(json, "desired_status")));
        }
    }

    static JsonNode field(JsonNode json, String name) {
        JsonNode value = json.get(name);
        if (value == null) {
            throw new IllegalArgumentException("missing \"" + name + "\"");
        }
        return value;
    }

    static int uid(JsonNode json, String name) {
        int uid = integer(json, name);
        if (uid < 0 || uid > 0xFFFF) {
            throw new IllegalArgumentException("\"" + name + "\" is not a 16-bit uid: " + uid);
        }
        return uid;
    }

    static int integer(JsonNode json, String name) {
        JsonNode value = field(json, name);
        if (!value.isIntegralNumber() || !value.canConvertToInt()) {
            throw new IllegalArgumentException("\"" + name + "\" must be an integer");
        }
        return value.intValue();
    }

    static boolean bool(JsonNode json, String name) {
        JsonNode value = field(json, name);
        if (!value.isBoolean()) {
            throw new IllegalArgumentException("\"" + name + "\" must be true or false");
        }
        return value.booleanValue();
    }

    static String text(JsonNode json, String name) {
        JsonNode value = field(json, name);
        if (!value.isTextual()) {
            throw new IllegalArgumentException("\"" + name + "\" must be a string");
        }
        return value.textValue();
    }

    /** BT.CPP's convertFromString for NodeStatus: the five names, nothing else. */
    static NodeStatus status(String name) {
        for (NodeStatus status : NodeStatus.values()) {
            if (status.name().equals(name)) {
                return status;
            }
        }
        throw new IllegalArgumentException("not a node status: " + name);
    }
}
