package org.miron.bt.nodes;

import static org.miron.bt.nodes.NodeCatalogue.BOTH;
import static org.miron.bt.nodes.NodeCatalogue.V3;
import static org.miron.bt.nodes.NodeCatalogue.V4;
import static org.miron.bt.nodes.NodeKind.*;
import static org.miron.bt.nodes.PortModel.inout;
import static org.miron.bt.nodes.PortModel.input;
import static org.miron.bt.nodes.PortModel.output;
import static org.miron.bt.nodes.PortType.*;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * The table: every built-in element of BehaviorTree.CPP 3.5–3.8 and 4.x that the BT grammar
 * parses, with the ports their providedPorts() declare (descriptions as the library writes them,
 * where it has one). The port names are constants so that code writing them (the executor, the
 * weaver) spells them once. Read it through {@link NodeCatalogue}.
 */
public final class BuiltinNodes {
    public static final String ID = "ID";
    public static final String SUCCESS_THRESHOLD = "success_threshold";
    public static final String FAILURE_THRESHOLD = "failure_threshold";
    public static final String SUCCESS_COUNT = "success_count";
    public static final String FAILURE_COUNT = "failure_count";
    public static final String MAX_FAILURES = "max_failures";
    public static final String VARIABLE = "variable";
    /** case_1 .. case_N of SwitchN. */
    public static final String CASE_PREFIX = "case_";
    public static final String NUM_CYCLES = "num_cycles";
    public static final String NUM_ATTEMPTS = "num_attempts";
    public static final String MSEC = "msec";
    public static final String DELAY_MSEC = "delay_msec";
    public static final String VALUE_A = "value_A";
    public static final String VALUE_B = "value_B";
    public static final String RETURN_ON_MISMATCH = "return_on_mismatch";
    public static final String VALUE = "value";
    public static final String OUTPUT_KEY = "output_key";
    public static final String KEY = "key";
    public static final String CODE = "code";
    public static final String IF = "if";
    public static final String ELSE = "else";
    public static final String THEN_SKIP = "then_skip";
    public static final String QUEUE = "queue";
    public static final String IF_EMPTY = "if_empty";
    public static final String ENTRY = "entry";
    public static final String SHARED_BLACKBOARD = "__shared_blackboard";
    public static final String V3_AUTOREMAP = "__autoremap";
    public static final String AUTOREMAP = "_autoremap";

    private static final Set<Integer> ONLY_3 = Set.of(V3);
    private static final Set<Integer> ONLY_4 = Set.of(V4);

    private BuiltinNodes() {
    }

    /** The entries, in the order of the grammar's ElementKeyword. */
    static List<NodeModel> table() {
        List<NodeModel> all = new ArrayList<>();
        all.addAll(controls());
        all.addAll(decorators());
        all.addAll(leaves());
        return all;
    }

    private static List<NodeModel> controls() {
        List<NodeModel> all = new ArrayList<>(List.of(
                NodeModel.of("Sequence", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "Ticks its children in order; fails at the first failure, succeeds when all succeed."),
                NodeModel.of("ReactiveSequence", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "A Sequence that ticks again from the first child at every tick."),
                NodeModel.of("SequenceStar", CONTROL, ONLY_3, Children.AT_LEAST_ONE,
                        "A Sequence that resumes at the failed child instead of starting over.")
                        .counterpart("SequenceWithMemory", true),
                NodeModel.of("SequenceWithMemory", CONTROL, ONLY_4, Children.AT_LEAST_ONE,
                        "A Sequence that resumes at the failed child instead of starting over.")
                        .counterpart("SequenceStar", true),
                NodeModel.of("AsyncSequence", CONTROL, ONLY_4, Children.AT_LEAST_ONE,
                        "A Sequence that returns RUNNING between two children (yields to the tree)."),
                NodeModel.of("Fallback", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "Ticks its children in order; succeeds at the first success, fails when all fail."),
                NodeModel.of("ReactiveFallback", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "A Fallback that ticks again from the first child at every tick."),
                NodeModel.of("FallbackStar", CONTROL, ONLY_3, Children.AT_LEAST_ONE,
                        "A Fallback that resumes at the running child (BehaviorTree.CPP 2; the seed's metamodel).")
                        .counterpart("Fallback", true),
                NodeModel.of("AsyncFallback", CONTROL, ONLY_4, Children.AT_LEAST_ONE,
                        "A Fallback that returns RUNNING between two children (yields to the tree)."),
                NodeModel.of("Parallel", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "Ticks all children; done when enough succeed or fail.").ports(
                        input(SUCCESS_THRESHOLD, INT, "number of childen which need to succeed to trigger a SUCCESS")
                                .mandatory().onlyIn(V3),
                        input(FAILURE_THRESHOLD, INT, "number of childen which need to fail to trigger a FAILURE")
                                .withDefault("1").onlyIn(V3),
                        input(SUCCESS_COUNT, INT, "number of children that need to succeed to trigger a SUCCESS")
                                .withDefault("-1").onlyIn(V4),
                        input(FAILURE_COUNT, INT, "number of children that need to fail to trigger a FAILURE")
                                .withDefault("1").onlyIn(V4)),
                NodeModel.of("ParallelAll", CONTROL, ONLY_4, Children.AT_LEAST_ONE,
                        "Ticks all children until all are done; fails when too many failed.").ports(
                        input(MAX_FAILURES, INT,
                                "If the number of children returning FAILURE exceeds this value, ParallelAll returns FAILURE")
                                .withDefault("1"))));
        for (int cases = 2; cases <= 6; cases++) {
            all.add(switchNode(cases));
        }
        all.addAll(List.of(
                NodeModel.of("IfThenElse", CONTROL, BOTH, Children.between(2, 3),
                        "Ticks the first child (the condition), then the second if it succeeded, else the third."),
                NodeModel.of("WhileDoElse", CONTROL, BOTH, Children.between(2, 3),
                        "An IfThenElse that checks its condition again at every tick."),
                NodeModel.of("Control", CONTROL, BOTH, Children.AT_LEAST_ONE,
                        "A control node the application registered, named by its ID.").explicit()
                        .ports(input(ID, STRING, "the registered node").mandatory())));
        return all;
    }

    private static NodeModel switchNode(int cases) {
        NodeModel node = NodeModel.of("Switch" + cases, CONTROL, BOTH, Children.exactly(cases + 1),
                "Ticks the child of the first case equal to variable, else the last child (the default)")
                .ports(input(VARIABLE, STRING, null).mandatory());
        for (int k = 1; k <= cases; k++) {
            node = node.ports(input(CASE_PREFIX + k, STRING, null).mandatory());
        }
        return node;
    }

    private static List<NodeModel> decorators() {
        PortModel[] blackboardCheck = {
                input(VALUE_A, ANY, null).mandatory(), input(VALUE_B, ANY, null).mandatory(),
                input(RETURN_ON_MISMATCH, STATUS, "the status when the values differ (FAILURE when unset)")
                        .oneOf("SUCCESS", "FAILURE", "RUNNING") };
        return List.of(
                NodeModel.of("ForceSuccess", DECORATOR, BOTH, Children.ONE,
                        "Returns SUCCESS when its child finishes, whatever the child returned."),
                NodeModel.of("ForceFailure", DECORATOR, BOTH, Children.ONE,
                        "Returns FAILURE when its child finishes, whatever the child returned."),
                NodeModel.of("Inverter", DECORATOR, BOTH, Children.ONE, "Swaps its child's SUCCESS and FAILURE."),
                NodeModel.of("Repeat", DECORATOR, BOTH, Children.ONE, "Ticks its child again while it succeeds.")
                        .ports(input(NUM_CYCLES, INT,
                                "Repeat a successful child up to N times. Use -1 to create an infinite loop.")
                                .mandatory().atLeast(-1)),
                NodeModel.of("Timeout", DECORATOR, BOTH, Children.ONE,
                        "Halts its child and fails when the child runs too long.")
                        .ports(input(MSEC, UNSIGNED,
                                "After a certain amount of time, halt() the child if it is still running.")
                                .mandatory()),
                NodeModel.of("RetryUntilSuccessful", DECORATOR, BOTH, Children.ONE,
                        "Ticks its child again while it fails.")
                        .ports(input(NUM_ATTEMPTS, INT,
                                "Execute again a failing child up to N times. Use -1 to create an infinite loop.")
                                .mandatory().atLeast(-1))
                        .spelling("RetryUntilSuccesful", V3, "BehaviorTree.CPP 3.5-3.6's spelling; 3.7 dropped it"),
                NodeModel.of("BlackboardCheckInt", DECORATOR, ONLY_3, Children.ONE,
                        "Ticks its child when value_A equals value_B as integers.").ports(blackboardCheck)
                        .counterpart("Precondition", false),
                NodeModel.of("BlackboardCheckDouble", DECORATOR, ONLY_3, Children.ONE,
                        "Ticks its child when value_A equals value_B as numbers.").ports(blackboardCheck)
                        .counterpart("Precondition", false),
                NodeModel.of("BlackboardCheckString", DECORATOR, ONLY_3, Children.ONE,
                        "Ticks its child when value_A equals value_B as text.").ports(blackboardCheck)
                        .counterpart("Precondition", false),
                NodeModel.of("KeepRunningUntilFailure", DECORATOR, BOTH, Children.ONE,
                        "Returns RUNNING while its child succeeds, FAILURE when it fails."),
                NodeModel.of("Delay", DECORATOR, BOTH, Children.ONE,
                        "Waits before ticking its child (BehaviorTree.CPP 3.8 and later).")
                        .ports(input(DELAY_MSEC, UNSIGNED, "Tick the child after a few milliseconds")
                                .mandatory()),
                NodeModel.of("Decorator", DECORATOR, BOTH, Children.ONE,
                        "A decorator the application registered, named by its ID.").explicit()
                        .ports(input(ID, STRING, "the registered node").mandatory()),
                NodeModel.of("Precondition", DECORATOR, ONLY_4, Children.ONE,
                        "Ticks its child when the script if is true, else returns else.").ports(
                        input(IF, STRING, null).mandatory(),
                        input(ELSE, STATUS, "Return status if condition is false").withDefault("FAILURE")
                                .oneOf("FAILURE", "SUCCESS", "SKIPPED", "RUNNING")),
                NodeModel.of("RunOnce", DECORATOR, ONLY_4, Children.ONE, "Ticks its child until it finishes once.")
                        .ports(input(THEN_SKIP, BOOL, "If true, skip after the first execution, otherwise return the "
                                + "same NodeStatus returned once by the child.").withDefault("true")),
                loop("LoopInt", INT), loop("LoopDouble", DOUBLE), loop("LoopString", STRING), loop("LoopBool", BOOL),
                NodeModel.of("SkipUnlessUpdated", DECORATOR, ONLY_4, Children.ONE,
                        "Skips its child unless the entry changed since the last tick.")
                        .ports(input(ENTRY, ANY, "Entry to check").mandatory()),
                NodeModel.of("WaitValueUpdate", DECORATOR, ONLY_4, Children.ONE,
                        "Returns RUNNING until the entry changes, then ticks its child.")
                        .ports(input(ENTRY, ANY, "Entry to check").mandatory()));
    }

    private static NodeModel loop(String tag, PortType element) {
        return NodeModel.of(tag, DECORATOR, ONLY_4, Children.ONE,
                "Ticks its child once per element of queue, popped into value.").ports(
                inout(QUEUE, ANY, "the elements, a blackboard queue or a literal list separated by ';'").mandatory(),
                input(IF_EMPTY, STATUS, "Status to return if queue is empty: SUCCESS, FAILURE, SKIPPED")
                        .withDefault("SUCCESS").oneOf("SUCCESS", "FAILURE", "SKIPPED"),
                output(VALUE, element, "the element of this iteration"));
    }

    private static List<NodeModel> leaves() {
        return List.of(
                NodeModel.of("SubTree", SUBTREE, BOTH, Children.NONE, "Runs the tree named by ID.").explicit().ports(
                        input(ID, STRING, "the tree").mandatory(),
                        input(SHARED_BLACKBOARD, BOOL, "If false (default) the subtree has its own blackboard and "
                                + "you need to do port remapping to connect it to the parent").withDefault("false")
                                .onlyIn(V3),
                        input(AUTOREMAP, BOOL, "If true, all the ports with the same name will be remapped")
                                .withDefault("false").onlyIn(V4)),
                NodeModel.of("SubTreePlus", SUBTREE, ONLY_3, Children.NONE,
                        "Runs the tree named by ID on its own blackboard; its other attributes remap or set entries.")
                        .explicit().counterpart("SubTree", false).ports(
                        input(ID, STRING, "the tree").mandatory(),
                        input(V3_AUTOREMAP, BOOL, "If true, all the ports with the same name will be remapped")
                                .withDefault("false"),
                        // Not among its providedPorts: Groot and the seed's trees write it, the loader ignores it.
                        input(SHARED_BLACKBOARD, BOOL, "ignored: a SubTreePlus always has its own blackboard")
                                .withDefault("false")),
                NodeModel.of("Action", ACTION, BOTH, Children.NONE,
                        "An action the application registered, named by its ID.").explicit()
                        .ports(input(ID, STRING, "the registered node").mandatory()),
                NodeModel.of("Condition", CONDITION, BOTH, Children.NONE,
                        "A condition the application registered, named by its ID.").explicit()
                        .ports(input(ID, STRING, "the registered node").mandatory()),
                NodeModel.of("AlwaysSuccess", ACTION, BOTH, Children.NONE, "Returns SUCCESS."),
                NodeModel.of("AlwaysFailure", ACTION, BOTH, Children.NONE, "Returns FAILURE."),
                NodeModel.of("SetBlackboard", ACTION, BOTH, Children.NONE,
                        "Writes value into the entry output_key and succeeds.").ports(
                        input(VALUE, ANY, "Value to be written into the output_key").mandatory(),
                        inout(OUTPUT_KEY, ANY, "Name of the blackboard entry where the value should be written")
                                .mandatory()),
                NodeModel.of("Script", ACTION, ONLY_4, Children.NONE, "Runs a script and succeeds.")
                        .ports(input(CODE, STRING, "Piece of code that can be parsed").mandatory()),
                NodeModel.of("ScriptCondition", CONDITION, ONLY_4, Children.NONE,
                        "Succeeds when its script is true.")
                        .ports(input(CODE, STRING, "Piece of code that can be parsed. Must return false or true")
                                .mandatory()),
                NodeModel.of("Sleep", ACTION, ONLY_4, Children.NONE, "Returns RUNNING for msec, then SUCCESS.")
                        .ports(input(MSEC, UNSIGNED, null).mandatory()),
                NodeModel.of("UnsetBlackboard", ACTION, ONLY_4, Children.NONE, "Removes an entry and succeeds.")
                        .ports(input(KEY, STRING, "Key of the entry to remove").mandatory()),
                NodeModel.of("WasEntryUpdated", ACTION, ONLY_4, Children.NONE,
                        "Succeeds when the entry changed since the last tick, else fails.")
                        .ports(input(ENTRY, ANY, "Entry to check").mandatory()));
    }
}
