package org.miron.dsl.validation;

/**
 * The stable issue code of every diagnostic of the RoQME language (see docs/issue-codes.md): a
 * code is {@code roqme.} plus a kebab-case name and never changes meaning once published, so tools
 * and quick fixes can rely on it while messages are reworded. MIRoN extends RoQME: its syntax and
 * reference rules and RoQME's checks report these codes in .miron files too; MIRoN's own checks
 * use {@link MironIssueCodes}. Issue data, where given, is documented on the constant.
 */
public final class RoqmeIssueCodes {
    private RoqmeIssueCodes() {
    }

    // ------------------------------------------------------------------ parsing and linking

    /** The text does not parse (lexer, parser or value-converter error), in .roqme and .miron files. */
    public static final String SYNTAX_ERROR = "roqme.syntax-error";
    /**
     * A reference names nothing visible. Data: the visible names of the expected kind closest to
     * the one written, nearest first, as they would be written here (may be empty).
     */
    public static final String UNKNOWN_REFERENCE = "roqme.unknown-reference";
    /**
     * A reference names nothing visible, but a file in the same folder, not imported yet, declares
     * it. Data: the import line to add, e.g. {@code import "base.roqme"} or (MIRoN)
     * {@code import "tree.bt" as t}, then the reference as written with that import, e.g.
     * {@code Base.battery}.
     */
    public static final String MISSING_IMPORT = "roqme.missing-import";
    /** A reference names an element of another kind (a context where a belief is expected). */
    public static final String WRONG_KIND_REFERENCE = "roqme.wrong-kind-reference";
    /** A reference whose name matches several elements (e.g. two imports exposing it). */
    public static final String AMBIGUOUS_REFERENCE = "roqme.ambiguous-reference";

    // ------------------------------------------------------------------ imports and names

    /** import "". */
    public static final String EMPTY_IMPORT = "roqme.empty-import";
    /** An import of a file kind the language cannot import. Data: the importable extensions. */
    public static final String IMPORT_NOT_ALLOWED = "roqme.import-not-allowed";
    /** A file that imports itself. */
    public static final String SELF_IMPORT = "roqme.self-import";
    /** An import path that names no file. */
    public static final String IMPORT_NOT_FOUND = "roqme.import-not-found";
    /** Two top-level elements with one name. Data: the name. */
    public static final String DUPLICATE_NAME = "roqme.duplicate-name";
    /** An enum literal written twice in one enum. Data: the literal. */
    public static final String DUPLICATE_LITERAL = "roqme.duplicate-literal";

    // ------------------------------------------------------------------ types and values

    /** A range whose lower bound is not below its upper bound. */
    public static final String EMPTY_RANGE = "roqme.empty-range";
    /** A precision that is zero or negative. */
    public static final String PRECISION_NOT_POSITIVE = "roqme.precision-not-positive";
    /** A param default outside the param's range. */
    public static final String DEFAULT_OUT_OF_RANGE = "roqme.default-out-of-range";
    /** A definition, default or assignment whose type is not the declared one. */
    public static final String TYPE_MISMATCH = "roqme.type-mismatch";
    /** A literal of one enum where another enum is declared. */
    public static final String ENUM_MISMATCH = "roqme.enum-mismatch";
    /** A belief reference outside [0,1]. */
    public static final String REFERENCE_OUT_OF_RANGE = "roqme.reference-out-of-range";
    /** A survival time that is zero or negative. */
    public static final String SURVIVAL_NOT_POSITIVE = "roqme.survival-not-positive";
    /** An observation pattern that is neither boolean nor an event. */
    public static final String PATTERN_TYPE = "roqme.pattern-type";

    // ------------------------------------------------------------------ timers and schedules

    /** A timer defined by something other than a period (a time) or schedule("cron"). */
    public static final String TIMER_DEFINITION = "roqme.timer-definition";
    /** A timer period that is zero or negative. */
    public static final String PERIOD_NOT_POSITIVE = "roqme.period-not-positive";
    /** schedule(...) without a valid five-field cron string; reported at the wrong field. */
    public static final String INVALID_SCHEDULE = "roqme.invalid-schedule";
    /** Warning: an offset on a schedule timer, which has no effect. */
    public static final String SCHEDULE_OFFSET = "roqme.schedule-offset";
    /** Warning: a paused timer that no observation of its file starts or resumes. */
    public static final String PAUSED_TIMER_NEVER_STARTED = "roqme.paused-timer-never-started";

    // ------------------------------------------------------------------ expressions

    /** An operator applied to operands of the wrong type. */
    public static final String OPERAND_TYPE = "roqme.operand-type";
    /** '=' or '!=' between values that cannot be compared. */
    public static final String INCOMPARABLE = "roqme.incomparable";
    /** A '?:' or 'while' condition that is not boolean. */
    public static final String CONDITION_TYPE = "roqme.condition-type";
    /** The branches of '?:' have different types. */
    public static final String BRANCH_TYPES = "roqme.branch-types";
    /** A repeat count that is zero or negative. */
    public static final String REPEAT_COUNT = "roqme.repeat-count";
    /** range(min, max) with min above max. */
    public static final String EMPTY_RANGE_EXPRESSION = "roqme.empty-range-expression";
    /** A built-in function called with the wrong number of arguments. */
    public static final String FUNCTION_ARITY = "roqme.function-arity";
}
