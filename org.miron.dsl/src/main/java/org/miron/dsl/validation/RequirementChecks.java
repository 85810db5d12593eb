package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;

import java.util.Set;

import org.eclipse.xtext.validation.Check;
import org.miron.dsl.miron.Implication;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BeliefExpression;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.Param;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.roqme.WhileExpression;
import org.miron.dsl.util.Evidence;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Formulas;
import org.miron.dsl.util.Types;

/**
 * Requirements (docs/requirements.md): boolean state formulas over what the monitor can read
 * (contexts, properties, params, varpoints), positive bounds, a probability in (0, 1), and temporal
 * operators and implies nowhere else. Operand types inside state formulas are RoQME's
 * ExpressionChecks' (which report them as miron.requirement-type inside a requirement); what the declared ranges make trivial or unsatisfiable is the generator's
 * analysis (MironValidator.checkRuleInteractions).
 */
public class RequirementChecks extends CheckSet {

    private static final MironPackage M = MironPackage.eINSTANCE;
    /** The functions a state formula may call: those of rules, evaluated on one instant (ExpressionToTree's). */
    private static final Set<String> STATE_FUNCTIONS = Set.of("abs", "sqrt", "exp", "pow", "min", "max");

    @Check
    public void checkRequirement(Requirement r) {
        if (r.getFormula() != null) {
            checkFormula(r, r.getFormula());
        }
        Double p = r.getProbability();
        if (p != null && (p <= 0 || p >= 1)) {
            error("the probability of requirement '" + r.getName() + "' must lie strictly between 0 and 1, not "
                    + Texts.fmt(p) + " (a requirement every run must meet has no 'with probability')", r,
                    M.getRequirement_Probability(), REQUIREMENT_PROBABILITY);
        }
    }

    /** Walks the temporal and boolean structure down to the state formulas, each of which must be boolean. */
    private void checkFormula(Requirement r, Expression e) {
        if (Formulas.isState(e)) {
            ExprType t = Types.typeOf(e);
            if (!t.isLogical() && !t.isUnknown()) {
                error("the state formula '" + Formulas.text(e) + "' of requirement '" + r.getName()
                        + "' must be boolean, not " + t, e, null, REQUIREMENT_TYPE);
            }
        } else if (e instanceof TemporalExpression t) {
            checkFormula(r, t.getTerm());
        } else if (e instanceof Implication i) {
            checkFormula(r, i.getLeft());
            checkFormula(r, i.getRight());
        } else if (e instanceof UnaryExpression u && Formulas.isConnective(u)) {
            checkFormula(r, u.getTerm());
        } else if (e instanceof BinaryExpression b && Formulas.isConnective(b)) {
            checkFormula(r, b.getLeft());
            checkFormula(r, b.getRight());
        } else {
            error("'" + Formulas.text(e) + "' computes with a temporal formula: only not, and, or and implies combine "
                    + "formulas (put the temporal operator outside the comparison)", e, null, REQUIREMENT_TYPE);
        }
    }

    @Check
    public void checkBound(TemporalExpression t) {
        if (t.getBound() != null && Evidence.exactMillis(t.getBound()) < 1) {
            error("the bound of '" + t.getOperator().getLiteral() + " within' must be at least 1 millisecond, not "
                    + Formulas.text(t.getBound()), t, M.getTemporalExpression_Bound(), REQUIREMENT_BOUND);
        }
    }

    @Check
    public void checkTemporalInRequirement(TemporalExpression t) {
        if (Formulas.requirementOf(t) == null) {
            error("'" + t.getOperator().getLiteral() + "' is a temporal operator: it is only allowed in a requirement",
                    t, M.getTemporalExpression_Operator(), REQUIREMENT_TEMPORAL_OUTSIDE);
        }
    }

    @Check
    public void checkImplicationInRequirement(Implication i) {
        if (Formulas.requirementOf(i) == null) {
            error("'implies' inside an expression is only allowed in a requirement (a rule's own 'implies' "
                    + "separates its condition from its consequences)", i, M.getImplication_Right(),
                    REQUIREMENT_TEMPORAL_OUTSIDE);
        }
    }

    /** Patterns, window functions and beliefs are observations' business: a requirement says time with its operators. */
    @Check
    public void checkNoPattern(Expression e) {
        if (Formulas.requirementOf(e) == null) {
            return;
        }
        String what = pattern(e);
        if (what != null) {
            error(what + " is not allowed in a requirement: patterns and window functions are RoQME observations' "
                    + "business, a requirement says time with always, never, eventually and within", e, null,
                    REQUIREMENT_PATTERN);
        }
    }

    /** The name of the pattern construct e is, or null. */
    private static String pattern(Expression e) {
        if (e instanceof FunctionCall f) {
            boolean state = STATE_FUNCTIONS.contains(f.getFunction())
                    && (!Set.of("min", "max").contains(f.getFunction()) || f.getArgs().size() == 2);
            return state ? null : "'" + f.getFunction() + "'";
        } else if (e instanceof UnaryExpression u && u.getOperator() == UnaryOperator.ONCE) {
            return "'once'";
        } else if (e instanceof BinaryExpression b && b.getOperator() == BinaryOperator.FOLLOWED_BY) {
            return "'->'";
        } else if (e instanceof WhileExpression) {
            return "'while'";
        } else if (e instanceof RepeatExpression) {
            return "'repeat'";
        } else if (e instanceof RangeExpression) {
            return "'range'";
        } else if (e instanceof BeliefExpression) {
            return "'belief'";
        } else if (e instanceof VariableRef ref && !readable(ref.getVariable())) {
            return "'" + Formulas.text(ref) + "' (" + ref.getVariable().eClass().getName().toLowerCase() + ")";
        }
        return null;
    }

    /** What the monitor reads: contexts, properties (estimates), params (their default), varpoints; unresolved: reported elsewhere. */
    private static boolean readable(Variable v) {
        return v == null || v.eIsProxy() || v instanceof Context || v instanceof Property || v instanceof Param
                || v instanceof VariationPoint;
    }
}
