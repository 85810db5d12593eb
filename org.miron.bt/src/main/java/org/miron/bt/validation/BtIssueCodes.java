package org.miron.bt.validation;

/**
 * The stable issue code of every diagnostic of the BT language (see docs/issue-codes.md). A code
 * is {@code bt.} plus a kebab-case name; once published it never changes meaning, so tools and
 * quick fixes can rely on it while the message text is reworded. Where a fix is obvious the
 * issue data carries what it needs, as documented on the constant.
 */
public final class BtIssueCodes {
    private BtIssueCodes() {
    }

    // ------------------------------------------------------------------ parsing and linking

    /** The file is not well-formed BT XML (parser, lexer or XML entity error). */
    public static final String SYNTAX_ERROR = "bt.syntax-error";
    /** A SubTree ID names no tree. Data: the closest visible tree IDs, nearest first (may be empty). */
    public static final String UNKNOWN_SUBTREE = "bt.unknown-subtree";
    /**
     * A SubTree ID that no visible tree has, but a .bt file in the same folder, not included yet,
     * defines. Data: the include to add, e.g. {@code <include path="nav.bt"/>}.
     */
    public static final String MISSING_INCLUDE = "bt.missing-include";
    /** Any other unresolved reference. Data: the closest visible names, nearest first. */
    public static final String UNKNOWN_REFERENCE = "bt.unknown-reference";

    // ------------------------------------------------------------------ files and trees

    /**
     * Several trees and no main_tree_to_execute. No longer reported for a file by itself (issue 17:
     * such a file is an include library, whichever files are loaded with it); kept for its meaning.
     */
    public static final String MAIN_TREE_REQUIRED = "bt.main-tree-required";
    /** main_tree_to_execute names no tree. Data: the closest visible tree IDs, nearest first. */
    public static final String UNKNOWN_MAIN_TREE = "bt.unknown-main-tree";
    /** An include path that does not resolve to a file. */
    public static final String INCLUDE_NOT_FOUND = "bt.include-not-found";
    /** A file that includes itself. */
    public static final String SELF_INCLUDE = "bt.self-include";
    /** A BehaviorTree without ID in a file with several trees (a file's single tree needs none). */
    public static final String TREE_WITHOUT_ID = "bt.tree-without-id";
    /** A BehaviorTree ID used twice (in the file or its includes) for different trees. */
    public static final String DUPLICATE_TREE_ID = "bt.duplicate-tree-id";
    /** A BehaviorTree defined again with the same content (a warning; references use the first). */
    public static final String DUPLICATE_IDENTICAL_TREE = "bt.duplicate-identical-tree";
    /** A second TreeNodesModel under root. */
    public static final String DUPLICATE_NODES_MODEL = "bt.duplicate-nodes-model";
    /** An included file that is not a behaviour-tree file (its root element is not root). */
    public static final String INCLUDE_NOT_BT = "bt.include-not-bt";
    /** An element under root that BehaviorTree.CPP ignores. Data: the closest element it reads, if any. */
    public static final String UNKNOWN_ELEMENT = "bt.unknown-element";
    /** A BehaviorTree with no root node. */
    public static final String TREE_WITHOUT_ROOT = "bt.tree-without-root";
    /** A BehaviorTree with more than one root node (reported on each extra root). */
    public static final String TREE_SEVERAL_ROOTS = "bt.tree-several-roots";

    // ------------------------------------------------------------------ node structure

    /** A control node without children. */
    public static final String CONTROL_WITHOUT_CHILDREN = "bt.control-without-children";
    /** IfThenElse / WhileDoElse without 2 or 3 children. */
    public static final String CONDITIONAL_CHILD_COUNT = "bt.conditional-child-count";
    /** A decorator (built-in or declared in TreeNodesModel) without exactly one child. */
    public static final String DECORATOR_CHILD_COUNT = "bt.decorator-child-count";
    /** Any other built-in whose number of children its catalogue entry does not admit. */
    public static final String CHILD_COUNT = "bt.child-count";
    /**
     * A leaf written with children: Action and Condition (errors, as in BehaviorTree.CPP), the
     * built-in leaves (warnings: BehaviorTree.CPP 3 loads them and drops the children), or a node
     * declared as an Action or a Condition in TreeNodesModel.
     */
    public static final String LEAF_WITH_CHILDREN = "bt.leaf-with-children";
    /** A closing tag that does not match its opening tag. Data: the tag to close, e.g. {@code Sequence}. */
    public static final String CLOSE_TAG_MISMATCH = "bt.close-tag-mismatch";
    /**
     * An element left open: the close tag of an element around it comes first. Reported on the
     * outer close tag's name. Data: the tag to close, e.g. {@code Sequence}.
     */
    public static final String UNCLOSED_ELEMENT = "bt.unclosed-element";

    // ------------------------------------------------------------------ attributes and ports

    /** A required attribute is missing. Data: the attribute's name. */
    public static final String MISSING_ATTRIBUTE = "bt.missing-attribute";
    /** An attribute written twice on one element. Data: the attribute's name. */
    public static final String DUPLICATE_ATTRIBUTE = "bt.duplicate-attribute";
    /** An integer port whose value is not an integer. */
    public static final String NOT_AN_INTEGER = "bt.not-an-integer";
    /** An integer port below its minimum. Data: the minimum. */
    public static final String INTEGER_TOO_SMALL = "bt.integer-too-small";
    /** A Parallel threshold that does not fit its number of children. */
    public static final String PARALLEL_THRESHOLD = "bt.parallel-threshold";
    /** return_on_mismatch of a BlackboardCheck that is not SUCCESS, FAILURE or RUNNING. */
    public static final String BAD_RETURN_ON_MISMATCH = "bt.bad-return-on-mismatch";
    /** Action, Condition, Control or Decorator without the ID of the registered node. */
    public static final String NODE_WITHOUT_ID = "bt.node-without-id";
    /** SubTree / SubTreePlus without ID. */
    public static final String SUBTREE_WITHOUT_ID = "bt.subtree-without-id";
    /** SwitchN without a variable attribute. */
    public static final String SWITCH_WITHOUT_VARIABLE = "bt.switch-without-variable";
    /** SwitchN without one of case_1..case_N. Data: the missing attribute, e.g. {@code case_2}. */
    public static final String SWITCH_MISSING_CASE = "bt.switch-missing-case";
    /** SwitchN with a case_k beyond N. Data: the attribute's name. */
    public static final String SWITCH_EXTRA_CASE = "bt.switch-extra-case";
    /** SwitchN without N+1 children. */
    public static final String SWITCH_CHILD_COUNT = "bt.switch-child-count";

    // ------------------------------------------------------------------ portability (warnings)

    /** RetryUntilSuccesful, the 3.5-3.6 spelling. Data: the replacement tag, {@code RetryUntilSuccessful}. */
    public static final String RETRY_OLD_SPELLING = "bt.retry-old-spelling";
    /** FallbackStar, unknown to BehaviorTree.CPP 3. Data: the replacement tags, {@code Fallback} first. */
    public static final String FALLBACK_STAR = "bt.fallback-star";
    /** Delay, registered from BehaviorTree.CPP 3.8 on. */
    public static final String DELAY_NEEDS_3_8 = "bt.delay-needs-3-8";
    /** A compact node that is neither a tree nor declared in TreeNodesModel. Data: the node's tag. */
    public static final String UNDECLARED_NODE = "bt.undeclared-node";
    /**
     * A compact tag naming a tree ({@code <Check/>}), which BehaviorTree.CPP 3.8 does not recognise.
     * Data: the element to write instead, e.g. {@code <SubTree ID="Check"/>}.
     */
    public static final String COMPACT_SUBTREE = "bt.compact-subtree";

    /**
     * A port reads a blackboard key that nothing in the file or its includes writes, while a written
     * key has a near-identical name (a warning: the typo {@code {targte}} beside {@code target}).
     * Data: the written keys it may mean, nearest first.
     */
    public static final String KEY_TYPO = "bt.key-typo";

    // ------------------------------------------------------------------ BehaviorTree.CPP versions (3 and 4)

    /** BTCPP_format other than 3 or 4. Data: {@code 4}. */
    public static final String UNSUPPORTED_FORMAT = "bt.unsupported-format";
    /**
     * An element BehaviorTree.CPP 4 removed, in a BTCPP_format="4" file. Data: the version-4
     * replacement tag, e.g. {@code SequenceWithMemory} (none when there is no direct one).
     */
    public static final String V3_ONLY_ELEMENT = "bt.v3-only-element";
    /**
     * A BehaviorTree.CPP 4 element in a version-3 file (no BTCPP_format). Data: the version-3
     * replacement tag when there is one, e.g. {@code SequenceStar}.
     */
    public static final String V4_ONLY_ELEMENT = "bt.v4-only-element";
    /** A version-3 attribute in a version-4 file (__shared_blackboard, success_threshold...). Data: the replacement attribute. */
    public static final String V3_ONLY_ATTRIBUTE = "bt.v3-only-attribute";
    /** A version-4 attribute in a version-3 file (_skipIf.._post, _autoremap, success_count...). Data: the replacement, if any. */
    public static final String V4_ONLY_ATTRIBUTE = "bt.v4-only-attribute";
    /**
     * {@code <Action ID="X">} (or Condition, Control, Decorator) directly under a ReactiveSequence
     * in a version-4 file: BehaviorTree.CPP 4 looks its children up by element name and rejects
     * it. Data: the compact tag, {@code X}.
     */
    public static final String REACTIVE_EXPLICIT_CHILD = "bt.reactive-explicit-child";
    /** A boolean port whose value is not true/false/1/0 (as BT.CPP converts it). */
    public static final String NOT_A_BOOLEAN = "bt.not-a-boolean";
    /** A port taking a node status (Precondition's else, a Loop's if_empty) given another value. */
    public static final String BAD_STATUS = "bt.bad-status";
    /** A Loop queue whose literal elements do not convert to the loop's type. */
    public static final String BAD_LOOP_QUEUE = "bt.bad-loop-queue";

    // ------------------------------------------------------------------ scripts (BehaviorTree.CPP 4)

    /** A script (code, if, _skipIf.._post) that BT.CPP's script parser rejects; reported at the offending character. */
    public static final String SCRIPT_SYNTAX_ERROR = "bt.script-syntax-error";
    /** An assignment whose left side is not a blackboard key (fails on every tick). */
    public static final String SCRIPT_ASSIGNMENT_TARGET = "bt.script-assignment-target";
    /** A string literal used with an arithmetic or bitwise operator (fails on every tick). */
    public static final String SCRIPT_TYPE_MISMATCH = "bt.script-type-mismatch";
    /**
     * A version-4 attribute starting with '_' that is no pre/post-condition but nearly one
     * ({@code _onSucess}, {@code _skipif}): BT.CPP 4 ignores it, so its script never runs (a warning).
     * Data: the condition names it may mean, nearest first.
     */
    public static final String CONDITION_TYPO = "bt.condition-typo";

    // ------------------------------------------------------------------ conversion (miron convert)

    /** An element of a version-4 file that BehaviorTree.CPP 3 cannot express (Script, Sleep, _skipIf...). */
    public static final String NO_V3_EQUIVALENT = "bt.no-v3-equivalent";
    /** An element of a version-3 file that BehaviorTree.CPP 4 cannot express (FallbackStar, a port named _skipIf...). */
    public static final String NO_V4_EQUIVALENT = "bt.no-v4-equivalent";
}
