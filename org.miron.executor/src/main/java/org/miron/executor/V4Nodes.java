package org.miron.executor;

import static org.miron.bt.nodes.BuiltinNodes.AUTOREMAP;
import static org.miron.bt.nodes.BuiltinNodes.ID;

import java.util.EnumMap;
import java.util.Map;

import org.miron.bt.bt.TreeNode;
import org.miron.executor.scripting.ScriptCode;
import org.miron.executor.scripting.ScriptCompiler;

/**
 * What version 4 adds to building any node: the entries its ports declare, the blackboard of a
 * SubTree, the pre/post-condition attributes and the scripts of Script, ScriptCondition and
 * Precondition, parsed here once (a script that does not parse is a build error). The version-4
 * nodes themselves are made by {@link BuiltinFactories#V4}.
 */
final class V4Nodes {
    private final Map<String, Integer> enums;

    V4Nodes(Map<String, Integer> enums) {
        this.enums = enums;
    }

    Map<String, Integer> enums() {
        return enums;
    }

    /** BT.CPP 4 creates, when building, an entry without a value for every port pointing at a key. */
    static void declarePorts(NodeInfo info) {
        info.ports().attributes().forEach((port, value) -> {
            if (!port.startsWith("_") && !port.equals("name") && !port.equals(ID)) {
                Ports.blackboardKey(port, value).ifPresent(info.ports().blackboard()::declare);
            }
        });
    }

    /**
     * The blackboard of a version-4 SubTree: always its own; {@code port="{parentKey}"} (or
     * {@code {=}}, the key of the same name) remaps, a literal is written into it as text,
     * {@code _autoremap="true"} makes every other key (not starting with '_') the parent's.
     */
    static Blackboard subtreeBlackboard(NodeInfo info, Blackboard parent) {
        Blackboard blackboard = parent.createChild();
        info.ports().bindInto(blackboard, port -> port.equals("name") || port.equals(ID) || port.startsWith("_"));
        String autoremap = info.ports().raw(AUTOREMAP);
        if (autoremap != null) {
            try {
                blackboard.setAutoRemap(Conversions.toBoolean(autoremap));
            } catch (IllegalArgumentException e) {
                throw new BtBuildException(info.path() + ": " + AUTOREMAP + ": " + e.getMessage(), e);
            }
        }
        return blackboard;
    }

    /** The pre/post-condition attributes of a node (possibly none), parsed. */
    Conditions conditions(TreeNode model, String path) {
        Map<Conditions.Kind, ScriptCode> scripts = new EnumMap<>(Conditions.Kind.class);
        for (Conditions.Kind kind : Conditions.Kind.values()) {
            String source = model.attribute(kind.attribute);
            if (source != null) {
                scripts.put(kind, compile(source, path, kind.attribute));
            }
        }
        return new Conditions(scripts, enums);
    }

    /** The script of a port (Script's code, Precondition's if), parsed. */
    static ScriptCode script(NodeInfo info, String port) {
        String source = info.ports().raw(port);
        if (source == null) {
            throw new BtBuildException(info.path() + ": missing parameter " + port);
        }
        return compile(source, info.path(), port);
    }

    private static ScriptCode compile(String source, String path, String attribute) {
        try {
            return ScriptCompiler.compile(source);
        } catch (IllegalArgumentException e) {
            throw new BtBuildException(path + ": " + attribute + ": " + e.getMessage(), e);
        }
    }
}
