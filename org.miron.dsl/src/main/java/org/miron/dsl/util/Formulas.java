package org.miron.dsl.util;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.miron.Implication;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.UnaryExpression;

/**
 * The structure of a requirement's formula (docs/requirements.md): temporal operators and
 * {@code implies} over boolean connectives over state formulas, a state formula being a
 * sub-expression without temporal operators and {@code implies}. Shared by the validator, the
 * generator and the editors so that they split a formula alike.
 */
public final class Formulas {
    private Formulas() {
    }

    /** Whether e has no temporal operator and no implies anywhere: one state formula (null, half-parsed, counts as one). */
    public static boolean isState(Expression e) {
        return e == null || !(e instanceof TemporalExpression || e instanceof Implication)
                && EcoreUtil2.getAllContentsOfType(e, TemporalExpression.class).isEmpty()
                && EcoreUtil2.getAllContentsOfType(e, Implication.class).isEmpty();
    }

    /** A boolean connective of formulas: not, and, or (and their &amp;, |, ! spellings). */
    public static boolean isConnective(Expression e) {
        if (e instanceof UnaryExpression u) {
            return switch (u.getOperator()) {
                case NOT, LOGICAL_NOT -> true;
                default -> false;
            };
        }
        if (e instanceof BinaryExpression b) {
            return switch (b.getOperator()) {
                case AND, OR, LOGICAL_AND, LOGICAL_OR -> true;
                default -> false;
            };
        }
        return false;
    }

    /** The requirement an element belongs to, or null outside requirements. */
    public static Requirement requirementOf(EObject e) {
        return EcoreUtil2.getContainerOfType(e, Requirement.class);
    }

    /** An element's source text on one line, whitespace and comments each one space. */
    public static String text(EObject e) {
        ICompositeNode node = e == null ? null : NodeModelUtils.findActualNodeFor(e);
        return node == null ? "" : NodeModelUtils.getTokenText(node).replaceAll("\\s+", " ").trim();
    }
}
