package org.miron.executor;

import static org.miron.bt.nodes.BuiltinNodes.CODE;
import static org.miron.bt.nodes.BuiltinNodes.FAILURE_COUNT;
import static org.miron.bt.nodes.BuiltinNodes.FAILURE_THRESHOLD;
import static org.miron.bt.nodes.BuiltinNodes.IF;
import static org.miron.bt.nodes.BuiltinNodes.MAX_FAILURES;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_COUNT;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_THRESHOLD;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeModel;
import org.miron.executor.actions.AlwaysFailureNode;
import org.miron.executor.actions.AlwaysSuccessNode;
import org.miron.executor.actions.EntryUpdatedNode;
import org.miron.executor.actions.ScriptConditionNode;
import org.miron.executor.actions.ScriptNode;
import org.miron.executor.actions.SetBlackboardNode;
import org.miron.executor.actions.SleepNode;
import org.miron.executor.actions.UnsetBlackboardNode;
import org.miron.executor.controls.IfThenElseNode;
import org.miron.executor.controls.OrderedNode;
import org.miron.executor.controls.OrderedNodeV4;
import org.miron.executor.controls.ParallelAllNode;
import org.miron.executor.controls.ParallelNode;
import org.miron.executor.controls.ParallelNodeV4;
import org.miron.executor.controls.ReactiveNode;
import org.miron.executor.controls.ReactiveNodeV4;
import org.miron.executor.controls.SwitchNode;
import org.miron.executor.controls.WhileDoElseNode;
import org.miron.executor.decorators.BlackboardCheckNode;
import org.miron.executor.decorators.DelayNode;
import org.miron.executor.decorators.EntryUpdatedDecorator;
import org.miron.executor.decorators.ForceNode;
import org.miron.executor.decorators.InverterNode;
import org.miron.executor.decorators.KeepRunningUntilFailureNode;
import org.miron.executor.decorators.LoopNode;
import org.miron.executor.decorators.LoopNodeV4;
import org.miron.executor.decorators.PreconditionNode;
import org.miron.executor.decorators.QueueLoopNode;
import org.miron.executor.decorators.RunOnceNode;
import org.miron.executor.decorators.TimeoutNode;

/**
 * The built-in nodes of each BehaviorTree.CPP version, as one factory per catalogue tag
 * ({@link NodeModel#tag()}; other spellings fold into it). The catalogue (org.miron.bt.nodes)
 * says which tags a version has, how many children and which ports they take, and
 * {@link BuiltinChecks} checks that before a factory runs, so an entry only makes its node (plus
 * the checks the catalogue cannot state, such as Parallel's thresholds against its children).
 * BuiltinFactoriesTest fails when the catalogue has a node of a version that its table lacks.
 */
final class BuiltinFactories {
    /** Makes a built-in from its info and its children, already built and counted. */
    @FunctionalInterface
    interface NodeFactory {
        /** @param enums the scripting enums (version 4's scripts and Switch read them) */
        Node create(NodeInfo info, List<Node> children, Map<String, Integer> enums);
    }

    static final Map<String, NodeFactory> V3 = v3();
    static final Map<String, NodeFactory> V4 = v4();

    /**
     * What an element of the other version's names is built as: its counterpart, when the
     * catalogue says renaming keeps the meaning (SequenceStar ⇄ SequenceWithMemory, as the
     * executor has always run them; FallbackStar → Fallback; RetryUntilSuccesful). The validator
     * rejects these in version 4 and warns in version 3; a tree built without it still runs.
     */
    private static final Map<Integer, Map<String, String>> RENAMES = Map.of(
            NodeCatalogue.V3, renames(NodeCatalogue.V3), NodeCatalogue.V4, renames(NodeCatalogue.V4));

    private BuiltinFactories() {
    }

    /** The factory table of a BehaviorTree.CPP version (3 or 4). */
    static Map<String, NodeFactory> table(int version) {
        return version == NodeCatalogue.V4 ? V4 : V3;
    }

    /**
     * The catalogue entry an element is built as in {@code version}: its own, or its renamed
     * counterpart; empty when the element names no built-in of the version (a node the
     * application registered, by its tag).
     */
    static Optional<NodeModel> builtin(String tag, int version) {
        Optional<NodeModel> own = NodeCatalogue.builtin(tag, version);
        if (own.isPresent() || tag == null) {
            return own;
        }
        String instead = RENAMES.get(version).get(tag);
        return instead == null ? Optional.empty() : NodeCatalogue.builtin(instead, version);
    }

    private static Map<String, String> renames(int version) {
        int other = version == NodeCatalogue.V3 ? NodeCatalogue.V4 : NodeCatalogue.V3;
        Map<String, String> renames = new LinkedHashMap<>();
        NodeCatalogue.onlyIn(other).forEach((tag, instead) -> {
            if (!instead.isEmpty() && NodeCatalogue.isRename(tag, instead)) {
                renames.put(tag, instead);
            }
        });
        return Map.copyOf(renames);
    }

    /** Checks a built-in against the catalogue, then makes it with its version's factory. */
    static Node create(NodeModel model, int version, NodeInfo info, List<Node> children, Map<String, Integer> enums) {
        NodeFactory factory = table(version).get(model.tag());
        if (factory == null) {
            // The catalogue has a node this executor cannot run (BuiltinFactoriesTest says which).
            throw new BtBuildException(info.path() + ": " + model.tag() + " is not supported by this executor");
        }
        BuiltinChecks.check(model, version, info, children.size());
        return factory.create(info, children, enums);
    }

    /** The nodes whose class is the same in both versions. */
    private static Map<String, NodeFactory> common() {
        Map<String, NodeFactory> t = new LinkedHashMap<>();
        t.put("IfThenElse", (i, c, e) -> new IfThenElseNode(i, c));
        t.put("WhileDoElse", (i, c, e) -> new WhileDoElseNode(i, c));
        t.put("ForceSuccess", (i, c, e) -> new ForceNode(i, c.get(0), NodeStatus.SUCCESS));
        t.put("ForceFailure", (i, c, e) -> new ForceNode(i, c.get(0), NodeStatus.FAILURE));
        t.put("Inverter", (i, c, e) -> new InverterNode(i, c.get(0)));
        t.put("Timeout", (i, c, e) -> new TimeoutNode(i, c.get(0)));
        t.put("KeepRunningUntilFailure", (i, c, e) -> new KeepRunningUntilFailureNode(i, c.get(0)));
        t.put("Delay", (i, c, e) -> new DelayNode(i, c.get(0)));
        t.put("AlwaysSuccess", (i, c, e) -> new AlwaysSuccessNode(i));
        t.put("AlwaysFailure", (i, c, e) -> new AlwaysFailureNode(i));
        t.put("SetBlackboard", (i, c, e) -> new SetBlackboardNode(i));
        return t;
    }

    private static Map<String, NodeFactory> v3() {
        Map<String, NodeFactory> t = common();
        t.put("Sequence", (i, c, e) -> OrderedNode.sequence(i, c));
        t.put("ReactiveSequence", (i, c, e) -> ReactiveNode.sequence(i, c));
        t.put("SequenceStar", (i, c, e) -> OrderedNode.sequenceStar(i, c));
        t.put("Fallback", (i, c, e) -> OrderedNode.fallback(i, c));
        t.put("ReactiveFallback", (i, c, e) -> ReactiveNode.fallback(i, c));
        t.put("FallbackStar", (i, c, e) -> OrderedNode.fallbackStar(i, c));
        t.put("Parallel", (i, c, e) -> {
            checkLiteral(i, SUCCESS_THRESHOLD, c.size(), ParallelNode::resolveThreshold);
            checkLiteral(i, FAILURE_THRESHOLD, c.size(), ParallelNode::resolveThreshold);
            return new ParallelNode(i, c);
        });
        switches(t, NodeCatalogue.V3);
        t.put("Repeat", (i, c, e) -> LoopNode.repeat(i, c.get(0)));
        t.put("RetryUntilSuccessful", (i, c, e) -> LoopNode.retry(i, c.get(0)));
        t.put("BlackboardCheckInt", (i, c, e) -> new BlackboardCheckNode(i, BlackboardCheckNode.Kind.INT, c.get(0)));
        t.put("BlackboardCheckDouble",
                (i, c, e) -> new BlackboardCheckNode(i, BlackboardCheckNode.Kind.DOUBLE, c.get(0)));
        t.put("BlackboardCheckString",
                (i, c, e) -> new BlackboardCheckNode(i, BlackboardCheckNode.Kind.STRING, c.get(0)));
        return Map.copyOf(t);
    }

    private static Map<String, NodeFactory> v4() {
        Map<String, NodeFactory> t = common();
        t.put("Sequence", (i, c, e) -> OrderedNodeV4.sequence(i, c, false));
        t.put("AsyncSequence", (i, c, e) -> OrderedNodeV4.sequence(i, c, true));
        t.put("SequenceWithMemory", (i, c, e) -> OrderedNodeV4.sequenceWithMemory(i, c));
        t.put("ReactiveSequence", (i, c, e) -> ReactiveNodeV4.sequence(i, c));
        t.put("Fallback", (i, c, e) -> OrderedNodeV4.fallback(i, c, false));
        t.put("AsyncFallback", (i, c, e) -> OrderedNodeV4.fallback(i, c, true));
        t.put("ReactiveFallback", (i, c, e) -> ReactiveNodeV4.fallback(i, c));
        t.put("Parallel", (i, c, e) -> {
            checkLiteral(i, SUCCESS_COUNT, c.size(), ParallelNodeV4::resolve);
            checkLiteral(i, FAILURE_COUNT, c.size(), ParallelNodeV4::resolve);
            return new ParallelNodeV4(i, c);
        });
        t.put("ParallelAll", (i, c, e) -> {
            checkLiteral(i, MAX_FAILURES, c.size(), ParallelNodeV4::resolve);
            return new ParallelAllNode(i, c);
        });
        switches(t, NodeCatalogue.V4);
        t.put("Repeat", (i, c, e) -> LoopNodeV4.repeat(i, c.get(0)));
        t.put("RetryUntilSuccessful", (i, c, e) -> LoopNodeV4.retry(i, c.get(0)));
        t.put("RunOnce", (i, c, e) -> new RunOnceNode(i, c.get(0)));
        t.put("Precondition", (i, c, e) -> new PreconditionNode(i, c.get(0), V4Nodes.script(i, IF), e));
        for (String loop : List.of("LoopInt", "LoopDouble", "LoopString", "LoopBool")) {
            t.put(loop, (i, c, e) -> new QueueLoopNode(i, c.get(0), QueueLoopNode.elementType(loop)));
        }
        t.put("SkipUnlessUpdated", (i, c, e) -> new EntryUpdatedDecorator(i, c.get(0), NodeStatus.SKIPPED));
        t.put("WaitValueUpdate", (i, c, e) -> new EntryUpdatedDecorator(i, c.get(0), NodeStatus.RUNNING));
        t.put("Script", (i, c, e) -> new ScriptNode(i, V4Nodes.script(i, CODE), e));
        t.put("ScriptCondition", (i, c, e) -> new ScriptConditionNode(i, V4Nodes.script(i, CODE), e));
        t.put("Sleep", (i, c, e) -> new SleepNode(i));
        t.put("UnsetBlackboard", (i, c, e) -> new UnsetBlackboardNode(i));
        t.put("WasEntryUpdated", (i, c, e) -> new EntryUpdatedNode(i));
        return Map.copyOf(t);
    }

    /** Switch2..SwitchN, as many as the catalogue has: SwitchN takes N cases and a default child. */
    private static void switches(Map<String, NodeFactory> table, int version) {
        boolean v4 = version == NodeCatalogue.V4;
        for (NodeModel node : NodeCatalogue.in(version)) {
            if (node.tag().matches("Switch\\d+")) {
                int cases = Integer.parseInt(node.tag().substring("Switch".length()));
                table.put(node.tag(), (i, c, e) -> new SwitchNode(i, cases, c, v4 ? e : null));
            }
        }
    }

    /** How a count port resolves against the number of children; throws when it cannot. */
    private interface Resolver {
        int resolve(String port, int written, int children);
    }

    /** A literal count must be one the children can meet (BT.CPP finds out when ticking). */
    private static void checkLiteral(NodeInfo info, String port, int children, Resolver resolver) {
        String value = info.ports().raw(port);
        if (value == null || Ports.blackboardKey(port, value).isPresent()) {
            return;
        }
        try {
            resolver.resolve(port, Conversions.toInt(value), children);
        } catch (IllegalArgumentException | BtRuntimeException e) {
            throw new BtBuildException(info.path() + ": " + e.getMessage(), e);
        }
    }
}
