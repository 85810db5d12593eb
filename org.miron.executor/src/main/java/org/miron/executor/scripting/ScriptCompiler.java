package org.miron.executor.scripting;

import java.util.ArrayList;
import java.util.List;

import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ScriptSyntaxError;
import org.miron.bt.script.ast.Assignment;
import org.miron.bt.script.ast.Binary;
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

/**
 * Parses a version-4 script once (with the BT language's {@link BtScripts}) and turns its syntax
 * tree into {@link ScriptCode}: a tree of closures, so ticks run it without parsing or walking
 * EMF objects. The operators follow BT.CPP 4 (scripting/operators.hpp); see {@link ScriptOperators}.
 */
public final class ScriptCompiler {
    private ScriptCompiler() {
    }

    /** The script, or IllegalArgumentException saying what is wrong with it and where (column, 1-based). */
    public static ScriptCode compile(String source) {
        ParsedScript parsed = BtScripts.parse(source);
        if (parsed.hasErrors()) {
            ScriptSyntaxError first = parsed.getErrors().get(0);
            throw new IllegalArgumentException("syntax error at column " + (first.getOffset() + 1) + " of '" + source + "': "
                    + first.getMessage());
        }
        List<Expression> statements = parsed.getScript().getStatements();
        if (statements.isEmpty()) {
            throw new IllegalArgumentException("empty script");
        }
        List<ScriptCode> compiled = new ArrayList<>();
        for (Expression statement : statements) {
            compiled.add(compile(statement));
        }
        if (compiled.size() == 1) {
            return compiled.get(0);
        }
        return scope -> {
            Object value = null;
            for (ScriptCode code : compiled) {
                value = code.run(scope);
            }
            return value;
        };
    }

    private static ScriptCode compile(Expression expression) {
        if (expression instanceof Parenthesized p) {
            return compile(p.getExpression());
        }
        if (expression instanceof BooleanLiteral b) {
            Long value = b.isValue() ? 1L : 0L;
            return scope -> value;
        }
        if (expression instanceof NumberLiteral n) {
            Object value = n.isReal() ? (Object) n.value() : (Object) (long) n.value();
            return scope -> value;
        }
        if (expression instanceof StringLiteral s) {
            String value = s.getValue();
            return scope -> value;
        }
        if (expression instanceof Name n) {
            String name = n.getName();
            return scope -> ScriptOperators.read(scope, name);
        }
        if (expression instanceof Unary u) {
            ScriptCode operand = compile(u.getOperand());
            return scope -> ScriptOperators.unary(u.getOperator(), operand.run(scope));
        }
        if (expression instanceof Binary b) {
            ScriptCode left = compile(b.getLeft());
            ScriptCode right = compile(b.getRight());
            return scope -> ScriptOperators.binary(b.getOperator(), left.run(scope), right.run(scope));
        }
        if (expression instanceof Comparison c) {
            List<ScriptCode> operands = new ArrayList<>();
            c.getOperands().forEach(o -> operands.add(compile(o)));
            List<ComparisonOperator> operators = List.copyOf(c.getOperators());
            return scope -> ScriptOperators.compareChain(scope, operators, operands);
        }
        if (expression instanceof Conditional c) {
            ScriptCode condition = compile(c.getCondition());
            ScriptCode then = compile(c.getThen());
            ScriptCode otherwise = compile(c.getElse());
            return scope -> ScriptValues.toDouble(condition.run(scope)) != 0 ? then.run(scope) : otherwise.run(scope);
        }
        if (expression instanceof Assignment a) {
            if (!(a.getTarget() instanceof Name target)) {
                throw new IllegalArgumentException("the left side of " + a.getOperator().getLiteral() + " must be a blackboard key");
            }
            String key = target.getName();
            ScriptCode value = compile(a.getValue());
            return scope -> ScriptOperators.assign(scope, key, a.getOperator(), value);
        }
        throw new IllegalArgumentException("unsupported script expression " + expression.eClass().getName());
    }
}
