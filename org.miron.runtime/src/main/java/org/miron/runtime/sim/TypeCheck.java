package org.miron.runtime.sim;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.script.ast.Assignment;
import org.miron.bt.script.ast.AssignmentOperator;
import org.miron.bt.script.ast.Binary;
import org.miron.bt.script.ast.BinaryOperator;
import org.miron.bt.script.ast.BooleanLiteral;
import org.miron.bt.script.ast.Comparison;
import org.miron.bt.script.ast.ComparisonOperator;
import org.miron.bt.script.ast.Conditional;
import org.miron.bt.script.ast.Expression;
import org.miron.bt.script.ast.Name;
import org.miron.bt.script.ast.NumberLiteral;
import org.miron.bt.script.ast.Parenthesized;
import org.miron.bt.script.ast.StringLiteral;
import org.miron.bt.script.ast.Unary;
import org.miron.bt.script.ast.UnaryOperator;

/**
 * Static types for world expressions written in BehaviorTree.CPP 4's script language, which
 * checks nothing before it runs: unknown names, assignments to what cannot be written, numbers
 * mixed with booleans or texts, an enum compared with a text that is none of its values. Also
 * collects the names an expression reads (a measure that reads nothing measures nothing).
 */
final class TypeCheck {
    /** A name an expression may use; {@code writable}: state a script may assign. */
    record Symbol(SimType type, boolean writable) {
    }

    /** A mistake at a character offset of the expression. */
    record Problem(int offset, String message) {
    }

    private final Map<String, Symbol> scope;
    final List<Problem> problems = new ArrayList<>();
    final Set<String> reads = new LinkedHashSet<>();
    final Set<String> writes = new LinkedHashSet<>();

    TypeCheck(Map<String, Symbol> scope) {
        this.scope = scope;
    }

    /** The type of a statement list (its last statement's), null after a problem. */
    SimType statements(List<Expression> statements) {
        SimType last = null;
        for (Expression e : statements) {
            last = type(e);
        }
        return last;
    }

    private SimType type(Expression e) {
        if (e instanceof Parenthesized p) {
            return type(p.getExpression());
        }
        if (e instanceof BooleanLiteral) {
            return SimType.BOOLEAN;
        }
        if (e instanceof NumberLiteral) {
            return SimType.NUMBER;
        }
        if (e instanceof StringLiteral s) {
            return new SimType(SimType.Kind.TEXT, List.of(s.getValue()), "'" + s.getValue() + "'");
        }
        if (e instanceof Name n) {
            Symbol s = scope.get(n.getName());
            if (s == null) {
                return fail(e, "unknown name '" + n.getName() + "' (not a state variable, parameter or built-in here)");
            }
            reads.add(n.getName());
            return s.type();
        }
        if (e instanceof Unary u) {
            SimType t = type(u.getOperand());
            if (t == null) {
                return null;
            }
            if (u.getOperator() == UnaryOperator.LOGICAL_NOT) {
                return expect(u.getOperand(), t, SimType.BOOLEAN, "!") ? SimType.BOOLEAN : null;
            }
            return expect(u.getOperand(), t, SimType.NUMBER, u.getOperator().getLiteral()) ? SimType.NUMBER : null;
        }
        if (e instanceof Binary b) {
            return binary(b);
        }
        if (e instanceof Comparison c) {
            return comparison(c);
        }
        if (e instanceof Conditional c) {
            SimType cond = type(c.getCondition());
            SimType then = type(c.getThen());
            SimType otherwise = type(c.getElse());
            if (cond == null || then == null || otherwise == null || !expect(c.getCondition(), cond, SimType.BOOLEAN, "?:")) {
                return null;
            }
            if (then.kind() != otherwise.kind() && then.kind() != SimType.Kind.ANY && otherwise.kind() != SimType.Kind.ANY) {
                return fail(c, "the branches of ?: differ: " + then + " and " + otherwise);
            }
            return then.kind() == SimType.Kind.TEXT ? merge(then, otherwise) : then;
        }
        if (e instanceof Assignment a) {
            return assignment(a);
        }
        return fail(e, "unsupported expression");
    }

    private static SimType merge(SimType a, SimType b) {
        if (a.literals() == null || b.literals() == null) {
            return SimType.TEXT;
        }
        List<String> all = new ArrayList<>(a.literals());
        b.literals().stream().filter(l -> !all.contains(l)).forEach(all::add);
        return new SimType(SimType.Kind.TEXT, all, "one of " + all);
    }

    private SimType binary(Binary b) {
        SimType l = type(b.getLeft());
        SimType r = type(b.getRight());
        if (l == null || r == null) {
            return null;
        }
        BinaryOperator op = b.getOperator();
        if (op == BinaryOperator.LOGIC_AND || op == BinaryOperator.LOGIC_OR) {
            return expect(b.getLeft(), l, SimType.BOOLEAN, op.getLiteral()) && expect(b.getRight(), r, SimType.BOOLEAN, op.getLiteral())
                    ? SimType.BOOLEAN : null;
        }
        if (op == BinaryOperator.CONCAT) {
            return SimType.TEXT;
        }
        return expect(b.getLeft(), l, SimType.NUMBER, op.getLiteral()) && expect(b.getRight(), r, SimType.NUMBER, op.getLiteral())
                ? SimType.NUMBER : null;
    }

    private SimType comparison(Comparison c) {
        List<SimType> types = new ArrayList<>();
        for (Expression o : c.getOperands()) {
            SimType t = type(o);
            if (t == null) {
                return null;
            }
            types.add(t);
        }
        for (int i = 0; i < c.getOperators().size(); i++) {
            SimType l = types.get(i);
            SimType r = types.get(i + 1);
            ComparisonOperator op = c.getOperators().get(i);
            boolean ordered = op != ComparisonOperator.EQUAL && op != ComparisonOperator.NOT_EQUAL;
            if (l.kind() == SimType.Kind.ANY || r.kind() == SimType.Kind.ANY) {
                continue;
            }
            if (l.kind() != r.kind()) {
                return fail(c, "cannot compare " + l + " with " + r + " (" + op.getLiteral() + ")");
            }
            if (ordered && l.kind() != SimType.Kind.NUMBER) {
                return fail(c, op.getLiteral() + " compares numbers, not " + l);
            }
            if (l.kind() == SimType.Kind.TEXT && !l.accepts(r) && !r.accepts(l)) {
                return fail(c, (l.literals() != null && l.literals().size() == 1 ? r : l) + " is never "
                        + (l.literals() != null && l.literals().size() == 1 ? l : r));
            }
        }
        return SimType.BOOLEAN;
    }

    private SimType assignment(Assignment a) {
        if (!(a.getTarget() instanceof Name target)) {
            return fail(a, "the left side of " + a.getOperator().getLiteral() + " must be a state variable");
        }
        Symbol s = scope.get(target.getName());
        if (s == null) {
            return fail(target, "unknown state variable '" + target.getName() + "'");
        }
        if (!s.writable()) {
            return fail(target, "'" + target.getName() + "' cannot be assigned (only state variables can)");
        }
        writes.add(target.getName());
        SimType v = type(a.getValue());
        if (v == null) {
            return null;
        }
        AssignmentOperator op = a.getOperator();
        if (op != AssignmentOperator.ASSIGN_CREATE && op != AssignmentOperator.ASSIGN_EXISTING) {
            return expect(target, s.type(), SimType.NUMBER, op.getLiteral()) && expect(a.getValue(), v, SimType.NUMBER, op.getLiteral())
                    ? s.type() : null;
        }
        if (!s.type().accepts(v)) {
            return fail(a.getValue(), "'" + target.getName() + "' is " + s.type() + ", the value is " + v);
        }
        return s.type();
    }

    private boolean expect(EObject at, SimType got, SimType wanted, String operator) {
        if (wanted.accepts(got)) {
            return true;
        }
        fail(at, operator + " needs " + wanted + ", not " + got);
        return false;
    }

    private SimType fail(EObject at, String message) {
        INode node = NodeModelUtils.getNode(at);
        problems.add(new Problem(node == null ? 0 : node.getOffset(), message));
        return null;
    }
}
