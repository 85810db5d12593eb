package org.miron.bt.validation;

import java.util.List;
import java.util.Map;
import java.util.Set;

/** What changed between BehaviorTree.CPP 3 and 4, as data shared by the validator and the converter. */
public final class BtVersions {
    private BtVersions() {
    }

    /** The pre/post-condition attributes BT.CPP 4 evaluates as scripts on any node. */
    public static final List<String> SCRIPT_DIRECTIVES = List.of("_successIf", "_failureIf", "_skipIf", "_while",
            "_onSuccess", "_onFailure", "_onHalted", "_post");

    /** Built-in tags BT.CPP 4 added, with the version-3 tag that means the same, or "" when none does. */
    public static final Map<String, String> V4_ONLY_TAGS = Map.ofEntries(
            Map.entry("SequenceWithMemory", "SequenceStar"), Map.entry("AsyncSequence", ""),
            Map.entry("AsyncFallback", ""), Map.entry("ParallelAll", ""), Map.entry("Script", ""),
            Map.entry("ScriptCondition", ""), Map.entry("Sleep", ""), Map.entry("UnsetBlackboard", ""),
            Map.entry("WasEntryUpdated", ""), Map.entry("Precondition", ""), Map.entry("RunOnce", ""),
            Map.entry("LoopInt", ""), Map.entry("LoopDouble", ""), Map.entry("LoopString", ""),
            Map.entry("LoopBool", ""), Map.entry("SkipUnlessUpdated", ""), Map.entry("WaitValueUpdate", ""));

    /** Tags BT.CPP 4 does not register, with what to write there instead. */
    public static final Map<String, String> V3_ONLY_TAGS = Map.of(
            "SequenceStar", "SequenceWithMemory", "SubTreePlus", "SubTree",
            "RetryUntilSuccesful", "RetryUntilSuccessful", "BlackboardCheckInt", "Precondition",
            "BlackboardCheckDouble", "Precondition", "BlackboardCheckString", "Precondition",
            "FallbackStar", "Fallback");

    /** Parallel's ports: version 3 name to version 4 name. */
    public static final Map<String, String> PARALLEL_PORTS = Map.of(
            "success_threshold", "success_count", "failure_threshold", "failure_count");

    /** BT.CPP's convertFromString&lt;bool&gt; accepts exactly these. */
    public static final Set<String> BOOLEANS = Set.of("true", "True", "TRUE", "false", "False", "FALSE", "1", "0");
}
