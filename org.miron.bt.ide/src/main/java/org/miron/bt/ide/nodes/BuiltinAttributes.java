package org.miron.bt.ide.nodes;

import java.util.List;
import java.util.Map;

/** The attributes BehaviorTree.CPP 3 and 4 read on their built-in nodes (besides `name`, which all have). */
public final class BuiltinAttributes {
    private static final List<String> SWITCH = List.of("variable", "case_1", "case_2", "case_3", "case_4", "case_5", "case_6");
    private static final List<String> BLACKBOARD_CHECK = List.of("value_A", "value_B", "return_on_mismatch");
    private static final List<String> LOOP = List.of("queue", "value", "if_empty");
    private static final Map<String, List<String>> BY_TAG = Map.ofEntries(
            // Version 3 names, then version 4 ones (the validator reports those of the other version).
            Map.entry("Parallel", List.of("success_threshold", "failure_threshold", "success_count", "failure_count")),
            Map.entry("Repeat", List.of("num_cycles")),
            Map.entry("RetryUntilSuccessful", List.of("num_attempts")),
            Map.entry("RetryUntilSuccesful", List.of("num_attempts")),
            Map.entry("Timeout", List.of("msec")),
            Map.entry("Delay", List.of("delay_msec")),
            Map.entry("SetBlackboard", List.of("value", "output_key")),
            Map.entry("BlackboardCheckInt", BLACKBOARD_CHECK),
            Map.entry("BlackboardCheckDouble", BLACKBOARD_CHECK),
            Map.entry("BlackboardCheckString", BLACKBOARD_CHECK),
            Map.entry("Switch2", SWITCH.subList(0, 3)),
            Map.entry("Switch3", SWITCH.subList(0, 4)),
            Map.entry("Switch4", SWITCH.subList(0, 5)),
            Map.entry("Switch5", SWITCH.subList(0, 6)),
            Map.entry("Switch6", SWITCH),
            Map.entry("SubTree", List.of("ID", "__shared_blackboard", "_autoremap")),
            Map.entry("SubTreePlus", List.of("ID", "__autoremap", "__shared_blackboard")),
            Map.entry("Action", List.of("ID")),
            Map.entry("Condition", List.of("ID")),
            Map.entry("Control", List.of("ID")),
            Map.entry("Decorator", List.of("ID")),
            // BehaviorTree.CPP 4
            Map.entry("ParallelAll", List.of("max_failures")),
            Map.entry("Script", List.of("code")),
            Map.entry("ScriptCondition", List.of("code")),
            Map.entry("Precondition", List.of("if", "else")),
            Map.entry("RunOnce", List.of("then_skip")),
            Map.entry("Sleep", List.of("msec")),
            Map.entry("LoopInt", LOOP),
            Map.entry("LoopDouble", LOOP),
            Map.entry("LoopString", LOOP),
            Map.entry("LoopBool", LOOP),
            Map.entry("UnsetBlackboard", List.of("key")),
            Map.entry("WasEntryUpdated", List.of("entry")),
            Map.entry("SkipUnlessUpdated", List.of("entry")),
            Map.entry("WaitValueUpdate", List.of("entry")));

    /** Built-in element names, as the grammar's ElementKeyword (BehaviorTree.CPP 3.5 .. 3.8, then 4). */
    public static final List<String> ELEMENTS = List.of("Sequence", "ReactiveSequence", "SequenceStar", "Fallback",
            "ReactiveFallback", "FallbackStar", "Parallel", "Switch2", "Switch3", "Switch4", "Switch5", "Switch6",
            "ForceSuccess", "ForceFailure", "Inverter", "Repeat", "Timeout", "RetryUntilSuccessful",
            "BlackboardCheckInt", "BlackboardCheckDouble", "BlackboardCheckString", "SubTree", "SubTreePlus", "Action",
            "Condition", "AlwaysSuccess", "AlwaysFailure", "SetBlackboard", "IfThenElse", "WhileDoElse", "Control",
            "KeepRunningUntilFailure", "Delay", "Decorator", "BehaviorTree", "include", "TreeNodesModel",
            "SequenceWithMemory", "AsyncSequence", "AsyncFallback", "ParallelAll", "Script", "ScriptCondition", "Sleep",
            "UnsetBlackboard", "WasEntryUpdated", "Precondition", "RunOnce", "LoopInt", "LoopDouble", "LoopString",
            "LoopBool", "SkipUnlessUpdated", "WaitValueUpdate");

    /** The values an attribute of a built-in can take, where they are a fixed set. */
    private static final Map<String, List<String>> VALUES = Map.of(
            "return_on_mismatch", List.of("SUCCESS", "FAILURE", "RUNNING"),
            "__shared_blackboard", List.of("true", "false"),
            "__autoremap", List.of("true", "false"),
            "_autoremap", List.of("true", "false"),
            "then_skip", List.of("true", "false"),
            "else", List.of("FAILURE", "SUCCESS", "SKIPPED", "RUNNING"),
            "if_empty", List.of("SUCCESS", "FAILURE", "SKIPPED"));

    private BuiltinAttributes() {
    }

    /** The fixed values of an attribute, or an empty list. */
    public static List<String> valuesOf(String attribute) {
        return VALUES.getOrDefault(attribute, List.of());
    }

    /** Null for a tag that is not a built-in with known attributes. */
    public static List<String> of(String tag) {
        return BY_TAG.get(tag);
    }
}
