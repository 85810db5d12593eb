package org.miron.executor;

import java.util.EnumMap;
import java.util.Map;
import org.miron.executor.scripting.ScriptCode;
import org.miron.executor.scripting.ScriptException;
import org.miron.executor.scripting.ScriptScope;
import org.miron.executor.scripting.ScriptValues;

/**
 * The pre- and post-condition attributes a version-4 node may carry, run around its tick in
 * BehaviorTree.CPP 4's order. Before the tick, while the node is IDLE: _failureIf, _successIf,
 * _skipIf (true: FAILURE, SUCCESS, SKIPPED instead of ticking), then _while (false: SKIPPED);
 * while it is RUNNING only _while counts (false: halt the node, SKIPPED). After a tick that
 * finished it: _onSuccess or _onFailure, then _post. _onHalted runs when the node is halted while
 * RUNNING.
 */
public final class Conditions {
    /** The attributes, in the order BT.CPP 4 evaluates them. */
    enum Kind {
        FAILURE_IF("_failureIf"), SUCCESS_IF("_successIf"), SKIP_IF("_skipIf"), WHILE("_while"),
        ON_HALTED("_onHalted"), ON_FAILURE("_onFailure"), ON_SUCCESS("_onSuccess"), POST("_post");

        final String attribute;

        Kind(String attribute) {
            this.attribute = attribute;
        }
    }

    private final Map<Kind, ScriptCode> scripts;
    private final Map<String, Integer> enums;

    Conditions(Map<Kind, ScriptCode> scripts, Map<String, Integer> enums) {
        this.scripts = scripts.isEmpty() ? Map.of() : new EnumMap<>(scripts);
        this.enums = enums;
    }

    /** The status the pre-conditions decide, or null to tick the node. */
    NodeStatus before(Node node) {
        if (scripts.isEmpty()) {
            return null;
        }
        if (node.status() == NodeStatus.IDLE) {
            if (isTrue(node, Kind.FAILURE_IF)) {
                return NodeStatus.FAILURE;
            }
            if (isTrue(node, Kind.SUCCESS_IF)) {
                return NodeStatus.SUCCESS;
            }
            if (isTrue(node, Kind.SKIP_IF)) {
                return NodeStatus.SKIPPED;
            }
            if (scripts.containsKey(Kind.WHILE) && !isTrue(node, Kind.WHILE)) {
                return NodeStatus.SKIPPED;
            }
        } else if (node.status() == NodeStatus.RUNNING && scripts.containsKey(Kind.WHILE) && !isTrue(node, Kind.WHILE)) {
            node.halt();
            return NodeStatus.SKIPPED;
        }
        return null;
    }

    void after(Node node, NodeStatus result) {
        run(node, result == NodeStatus.SUCCESS ? Kind.ON_SUCCESS : Kind.ON_FAILURE);
        run(node, Kind.POST);
    }

    void halted(Node node) {
        run(node, Kind.ON_HALTED);
    }

    private boolean isTrue(Node node, Kind kind) {
        if (!scripts.containsKey(kind)) {
            return false;
        }
        Object value = run(node, kind);
        try {
            return ScriptValues.toBoolean(value);
        } catch (ScriptException e) {
            throw new BtRuntimeException(node.path() + ": " + kind.attribute + ": " + e.getMessage(), e);
        }
    }

    private Object run(Node node, Kind kind) {
        ScriptCode script = scripts.get(kind);
        if (script == null) {
            return null;
        }
        return runScript(script, node, kind.attribute, enums);
    }

    /** Runs a script of a node, turning its failure into the node's runtime error. */
    public static Object runScript(ScriptCode script, Node node, String attribute, Map<String, Integer> enums) {
        try {
            return script.run(new ScriptScope(node.ports().blackboard(), enums));
        } catch (ScriptException e) {
            throw new BtRuntimeException(node.path() + ": " + attribute + ": " + e.getMessage(), e);
        }
    }
}
