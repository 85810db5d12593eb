package org.miron.dsl.validation;

/**
 * The stable issue codes of MIRoN's own checks (see docs/issue-codes.md): {@code miron.} plus a
 * kebab-case name. A .miron file also reports {@link RoqmeIssueCodes} for what MIRoN inherits from
 * RoQME: syntax, references, imports, names, types and expressions.
 */
public final class MironIssueCodes {
    private MironIssueCodes() {
    }

    // ------------------------------------------------------------------ imports

    /** Two imports with one alias. Data: the alias. */
    public static final String DUPLICATE_ALIAS = "miron.duplicate-alias";

    // ------------------------------------------------------------------ varpoint types

    /** A behavior tree enum without a preset literal. */
    public static final String PRESET_MISSING = "miron.preset-missing";
    /** A behavior tree enum with a second preset literal. */
    public static final String PRESET_DUPLICATE = "miron.preset-duplicate";
    /** A sample outside its type's range. */
    public static final String SAMPLE_OUT_OF_RANGE = "miron.sample-out-of-range";
    /** A sample off its type's precision grid. */
    public static final String SAMPLE_OFF_GRID = "miron.sample-off-grid";
    /** A sample declared twice. */
    public static final String SAMPLE_DUPLICATE = "miron.sample-duplicate";
    /** A varpoint's initial value ({@code := v}) that is not one of its values. */
    public static final String INITIAL_NOT_A_VALUE = "miron.initial-not-a-value";
    /** Two impacts on one property. */
    public static final String IMPACT_DUPLICATE = "miron.impact-duplicate";

    // ------------------------------------------------------------------ bindings

    /** An enum varpoint bound to the architecture. */
    public static final String ENUM_ARCH_BINDING = "miron.enum-arch-binding";
    /** A numeric varpoint bound to a node without an XPath to a port. */
    public static final String NUMERIC_BINDING_NEEDS_XPATH = "miron.numeric-binding-needs-xpath";
    /** An XPath that does not parse or cannot be evaluated. */
    public static final String XPATH_ERROR = "miron.xpath-error";
    /** An XPath that selects nothing in its target. */
    public static final String XPATH_SELECTS_NOTHING = "miron.xpath-selects-nothing";
    /** A numeric varpoint whose XPath selects something that is not an attribute. */
    public static final String XPATH_NOT_ATTRIBUTE = "miron.xpath-not-attribute";
    /** A before/after insertion or a behavior tree varpoint whose XPath selects something that is not a node. */
    public static final String XPATH_NOT_TREE_NODE = "miron.xpath-not-tree-node";
    /** The nominal BT file (none imported names a main tree) holds several trees and no main_tree_to_execute. */
    public static final String NOMINAL_TREE_WITHOUT_MAIN = "miron.nominal-tree-without-main";
    /** Two varpoints bound 'in' the same node or port. */
    public static final String SHARED_TARGET = "miron.shared-target";

    // ------------------------------------------------------------------ rules

    /** Rules that can apply together and cannot hold together (warning; the witness situation in the message). */
    public static final String RULE_CONFLICT = "miron.rule-conflict";
    /** A rule whose condition is false in every situation the rule check tried (warning). */
    public static final String RULE_NEVER_APPLIES = "miron.rule-never-applies";
    /** A rule dropped for higher rules whenever it applies (warning). */
    public static final String RULE_SHADOWED = "miron.rule-shadowed";
    /** The rule check's time budget ran out before every situation was tried (warning). */
    public static final String RULE_CHECK_CUT = "miron.rule-check-cut";
    /** A rule condition that is not boolean. */
    public static final String RULE_CONDITION_TYPE = "miron.rule-condition-type";
    /** A rule consequence that is not a boolean constraint. */
    public static final String CONSEQUENCE_TYPE = "miron.consequence-type";
    /** A rule consequence that constrains no varpoint. */
    public static final String CONSEQUENCE_WITHOUT_VARPOINT = "miron.consequence-without-varpoint";
    /** varpoint = value in a consequence, with a value outside the varpoint's range. */
    public static final String VALUE_OUT_OF_RANGE = "miron.value-out-of-range";
    /** varpoint = value in a consequence, with a value off the varpoint's precision grid. */
    public static final String VALUE_OFF_GRID = "miron.value-off-grid";

    // ------------------------------------------------------------------ requirements (docs/requirements.md)

    /** A state formula of a requirement that is not boolean. */
    public static final String REQUIREMENT_TYPE = "miron.requirement-type";
    /** A name inside a requirement that denotes nothing visible (a linking error). Data: the closest names. */
    public static final String REQUIREMENT_UNKNOWN_NAME = "miron.requirement-unknown-name";
    /** A temporal bound ({@code within t}) that is not positive. */
    public static final String REQUIREMENT_BOUND = "miron.requirement-bound";
    /** {@code with probability >= p} with p outside (0, 1). */
    public static final String REQUIREMENT_PROBABILITY = "miron.requirement-probability";
    /** A pattern, window function or belief in a requirement. */
    public static final String REQUIREMENT_PATTERN = "miron.requirement-pattern";
    /** A temporal operator or {@code implies} outside a requirement. */
    public static final String REQUIREMENT_TEMPORAL_OUTSIDE = "miron.requirement-temporal-outside";
    /** A requirement no run can violate given the declared ranges (warning). */
    public static final String REQUIREMENT_TRIVIAL = "miron.requirement-trivial";
    /** A requirement no run can meet given the declared ranges (warning). */
    public static final String REQUIREMENT_UNSATISFIABLE = "miron.requirement-unsatisfiable";
}
