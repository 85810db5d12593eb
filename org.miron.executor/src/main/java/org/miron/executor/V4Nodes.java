package org.miron.executor;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

import org.miron.bt.bt.TreeNode;
import org.miron.executor.actions.EntryUpdatedNode;
import org.miron.executor.actions.ScriptConditionNode;
import org.miron.executor.actions.ScriptNode;
import org.miron.executor.actions.SleepNode;
import org.miron.executor.actions.UnsetBlackboardNode;
import org.miron.executor.controls.OrderedNodeV4;
import org.miron.executor.controls.ParallelAllNode;
import org.miron.executor.controls.ParallelNodeV4;
import org.miron.executor.controls.ReactiveNodeV4;
import org.miron.executor.decorators.EntryUpdatedDecorator;
import org.miron.executor.decorators.LoopNode;
import org.miron.executor.decorators.LoopNodeV4;
import org.miron.executor.decorators.PreconditionNode;
import org.miron.executor.decorators.QueueLoopNode;
import org.miron.executor.decorators.RunOnceNode;
import org.miron.executor.scripting.ScriptCode;
import org.miron.executor.scripting.ScriptCompiler;

/**
 * The nodes whose version-4 behaviour differs from version 3's, or that only version 4 has, made
 * by element name (BT.CPP 4's built-in node IDs), and the pre/post-condition attributes of every
 * version-4 node. Scripts are parsed here, once; a script that does not parse is a build error.
 */
final class V4Nodes {
    private final Map<String, Integer> enums;

    V4Nodes(Map<String, Integer> enums) {
        this.enums = enums;
    }

    /** How many children a built-in takes. */
    private enum Shape { CONTROL, DECORATOR, LEAF }

    /** The built-in version-4 nodes made here, by tag. */
    private static final Map<String, Shape> BUILTINS = Map.ofEntries(
            Map.entry("Sequence", Shape.CONTROL), Map.entry("AsyncSequence", Shape.CONTROL),
            Map.entry("Fallback", Shape.CONTROL), Map.entry("AsyncFallback", Shape.CONTROL),
            Map.entry("SequenceWithMemory", Shape.CONTROL), Map.entry("SequenceStar", Shape.CONTROL),
            Map.entry("ReactiveSequence", Shape.CONTROL), Map.entry("ReactiveFallback", Shape.CONTROL),
            Map.entry("Parallel", Shape.CONTROL), Map.entry("ParallelAll", Shape.CONTROL),
            Map.entry("Repeat", Shape.DECORATOR), Map.entry("RetryUntilSuccessful", Shape.DECORATOR),
            Map.entry("RunOnce", Shape.DECORATOR), Map.entry("Precondition", Shape.DECORATOR),
            Map.entry("LoopInt", Shape.DECORATOR), Map.entry("LoopDouble", Shape.DECORATOR),
            Map.entry("LoopString", Shape.DECORATOR), Map.entry("LoopBool", Shape.DECORATOR),
            Map.entry("SkipUnlessUpdated", Shape.DECORATOR), Map.entry("WaitValueUpdate", Shape.DECORATOR),
            Map.entry("Script", Shape.LEAF), Map.entry("ScriptCondition", Shape.LEAF), Map.entry("Sleep", Shape.LEAF),
            Map.entry("UnsetBlackboard", Shape.LEAF), Map.entry("WasEntryUpdated", Shape.LEAF));

    /** Whether {@code tag} is a built-in version-4 node made here. */
    static boolean isV4Builtin(String tag) {
        return BUILTINS.containsKey(tag);
    }

    /** The node for a built-in version-4 tag, with its already built children. */
    Node create(String tag, NodeInfo info, List<Node> children) {
        String where = info.path();
        switch (BUILTINS.get(tag)) {
            case LEAF:
                if (!children.isEmpty()) {
                    throw new BtBuildException(where + ": " + tag + " takes no children");
                }
                break;
            case DECORATOR:
                if (children.size() != 1) {
                    throw new BtBuildException(where + ": a decorator has exactly one child, " + tag + " has " + children.size());
                }
                break;
            default:
                if (children.isEmpty()) {
                    throw new BtBuildException(where + ": a control node needs at least one child");
                }
        }
        Node child = children.isEmpty() ? null : children.get(0);
        switch (tag) {
            case "Sequence":
            case "AsyncSequence":
                return OrderedNodeV4.sequence(info, children, tag.startsWith("Async"));
            case "Fallback":
            case "AsyncFallback":
                return OrderedNodeV4.fallback(info, children, tag.startsWith("Async"));
            case "SequenceWithMemory":
            case "SequenceStar":
                return OrderedNodeV4.sequenceWithMemory(info, children);
            case "ReactiveSequence":
                return ReactiveNodeV4.sequence(info, children);
            case "ReactiveFallback":
                return ReactiveNodeV4.fallback(info, children);
            case "Parallel":
                checkCount(info, ParallelNodeV4.SUCCESS_COUNT, children.size());
                checkCount(info, ParallelNodeV4.FAILURE_COUNT, children.size());
                return new ParallelNodeV4(info, children);
            case "ParallelAll":
                checkCount(info, ParallelAllNode.MAX_FAILURES, children.size());
                return new ParallelAllNode(info, children);
            case "Repeat":
                requirePort(info, LoopNode.NUM_CYCLES);
                return LoopNodeV4.repeat(info, child);
            case "RetryUntilSuccessful":
                requirePort(info, LoopNode.NUM_ATTEMPTS);
                return LoopNodeV4.retry(info, child);
            case "RunOnce":
                return new RunOnceNode(info, child);
            case "Precondition":
                return new PreconditionNode(info, child, script(info, "if"), enums);
            case "Script":
                return new ScriptNode(info, script(info, "code"), enums);
            case "ScriptCondition":
                return new ScriptConditionNode(info, script(info, "code"), enums);
            case "Sleep":
                requirePort(info, SleepNode.MSEC);
                return new SleepNode(info);
            case "UnsetBlackboard":
                return new UnsetBlackboardNode(info);
            case "WasEntryUpdated":
                return new EntryUpdatedNode(info);
            case "SkipUnlessUpdated":
                return new EntryUpdatedDecorator(info, child, NodeStatus.SKIPPED);
            case "WaitValueUpdate":
                return new EntryUpdatedDecorator(info, child, NodeStatus.RUNNING);
            default:
                Function<String, Object> element = QueueLoopNode.elementType(tag);
                if (element != null) {
                    return new QueueLoopNode(info, child, element);
                }
                throw new BtBuildException(where + ": unsupported version-4 node " + tag);
        }
    }

    /** BT.CPP 4 creates, when building, an entry without a value for every port pointing at a key. */
    static void declarePorts(NodeInfo info) {
        info.ports().attributes().forEach((port, value) -> {
            if (!port.startsWith("_") && !port.equals("name") && !port.equals("ID")) {
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
        info.ports().bindInto(blackboard, port -> port.equals("name") || port.equals("ID") || port.startsWith("_"));
        String autoremap = info.ports().raw("_autoremap");
        if (autoremap != null) {
            try {
                blackboard.setAutoRemap(Conversions.toBoolean(autoremap));
            } catch (IllegalArgumentException e) {
                throw new BtBuildException(info.path() + ": _autoremap: " + e.getMessage(), e);
            }
        }
        return blackboard;
    }

    /** The child elements of a model node, whatever metamodel class the grammar gave it. */
    static List<TreeNode> children(TreeNode node) {
        if (node instanceof org.miron.bt.bt.ControlNode control) {
            return control.getNodes();
        }
        if (node instanceof org.miron.bt.bt.DecoratorNode decorator) {
            List<TreeNode> children = new java.util.ArrayList<>();
            if (decorator.getNode() != null) {
                children.add(decorator.getNode());
            }
            children.addAll(decorator.getSurplus());
            return children;
        }
        return List.of();
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

    private static ScriptCode script(NodeInfo info, String port) {
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

    private static void requirePort(NodeInfo info, String port) {
        if (info.ports().raw(port) == null) {
            throw new BtBuildException(info.path() + ": missing parameter " + port);
        }
    }

    /** A literal count must be an integer the children can meet (BT.CPP 4 finds out when ticking). */
    private static void checkCount(NodeInfo info, String port, int children) {
        String value = info.ports().raw(port);
        if (value == null || Ports.blackboardKey(port, value).isPresent()) {
            return;
        }
        try {
            ParallelNodeV4.resolve(port, Conversions.toInt(value), children);
        } catch (IllegalArgumentException | BtRuntimeException e) {
            throw new BtBuildException(info.path() + ": " + e.getMessage(), e);
        }
    }
}
