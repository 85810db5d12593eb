package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;
import static org.miron.dsl.validation.Texts.fmt;
import static org.miron.dsl.validation.Texts.range;

import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.validation.Check;
import org.miron.dsl.miron.Constraint;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Types;

/** Adaptation rules: boolean conditions, consequences that constrain varpoints with possible values. */
public class RuleChecks extends CheckSet {

    private static final MironPackage M = MironPackage.eINSTANCE;
    private static final RoqmePackage R = RoqmePackage.eINSTANCE;

    @Check
    public void checkRule(Rule rule) {
        if (rule.getCondition() != null) {
            ExprType t = Types.typeOf(rule.getCondition().getTerm());
            if (t.kind != ExprType.Kind.BOOLEAN && !t.isUnknown()) {
                error("the condition of rule '" + rule.getName() + "' must be boolean, not " + t, rule.getCondition(),
                        M.getCondition_Term(), RULE_CONDITION_TYPE);
            }
        }
        for (Constraint c : rule.getImplies()) {
            ExprType t = Types.typeOf(c.getTerm());
            if (t.kind != ExprType.Kind.BOOLEAN && !t.isUnknown()) {
                error("consequence of rule '" + rule.getName() + "' must be a boolean constraint, not " + t, c,
                        M.getConstraint_Term(), CONSEQUENCE_TYPE);
            } else if (!constrainsVarpoint(c)) {
                error("consequence of rule '" + rule.getName() + "' does not constrain any varpoint", c,
                        M.getConstraint_Term(), CONSEQUENCE_WITHOUT_VARPOINT);
            }
        }
    }

    /**
     * varpoint = number, in a rule consequence, with a number the varpoint can never take (outside
     * its range or off its precision grid): the rule could never be satisfied.
     */
    @Check
    public void checkConsequenceValue(Constraint c) {
        for (BinaryExpression e : EcoreUtil2.getAllContentsOfType(c, BinaryExpression.class)) {
            checkAssignedValue(e, e.getLeft(), e.getRight());
            checkAssignedValue(e, e.getRight(), e.getLeft());
        }
    }

    private void checkAssignedValue(BinaryExpression e, Expression side,
            Expression value) {
        if (e.getOperator() != BinaryOperator.EQ || !(side instanceof VariableRef)
                || !(((VariableRef) side).getVariable() instanceof VariationPoint)) {
            return;
        }
        Double v = numberOf(value);
        DataType type = Types.dataType(((VariableRef) side).getVariable());
        if (v == null || !(type instanceof NumericType)) {
            return;
        }
        NumericType n = (NumericType) type;
        String name = ((VariableRef) side).getVariable().getName();
        EReference feature = value == e.getRight() ? R.getBinaryExpression_Right() : R.getBinaryExpression_Left();
        if ((n.getLower() != null && v < n.getLower()) || (n.getUpper() != null && v > n.getUpper())) {
            error("varpoint '" + name + "' can never be " + fmt(v) + ": it is outside its range " + range(n), e, feature,
                    VALUE_OUT_OF_RANGE);
        } else if (n.getPrecision() != null && n.getPrecision() > 0 && !VariationPointTypeChecks.onGrid(v, n)) {
            error("varpoint '" + name + "' can never be " + fmt(v) + ": it is not on its precision grid "
                    + fmt(n.getLower() == null ? 0 : n.getLower()) + " + k*" + fmt(n.getPrecision()), e, feature, VALUE_OFF_GRID);
        }
    }

    /** The value of a literal number, possibly negated; null for anything else. */
    private static Double numberOf(Expression e) {
        if (e instanceof NumericValue) {
            return ((NumericValue) e).getValue();
        } else if (e instanceof UnaryExpression
                && ((UnaryExpression) e).getOperator() == UnaryOperator.MINUS) {
            Double inner = numberOf(((UnaryExpression) e).getTerm());
            return inner == null ? null : -inner;
        }
        return null;
    }

    /** Whether a consequence mentions a variation point (unresolved references count as yes). */
    private static boolean constrainsVarpoint(Constraint c) {
        for (VariableRef ref : EcoreUtil2.getAllContentsOfType(c, VariableRef.class)) {
            if (ref.getVariable() == null || ref.getVariable().eIsProxy() || ref.getVariable() instanceof VariationPoint) {
                return true;
            }
        }
        return false;
    }
}
