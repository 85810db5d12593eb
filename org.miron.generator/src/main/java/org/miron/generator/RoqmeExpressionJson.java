package org.miron.generator;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.EcoreUtil2;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BeliefExpression;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.BooleanValue;
import org.miron.dsl.roqme.ConditionalExpression;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.EventValue;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.SequenceValue;
import org.miron.dsl.roqme.StringValue;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;
import org.miron.dsl.roqme.Value;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.roqme.WhileExpression;
import org.miron.dsl.roqme.util.RoqmeSwitch;
import org.miron.dsl.util.Evidence;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A RoQME expression as a runtime-model Expr node (docs/roqme-model.md): one shape per node plus
 * its static type as the validator computes it ({@link Types}). Dispatches on roqme.ecore's
 * switch: an expression class without a case reaches {@link #defaultCase} and is refused as
 * unsupported, never written half.
 */
final class RoqmeExpressionJson extends RoqmeSwitch<ObjectNode> {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private final RoqmeDeclarations declarations;
    private final List<GenerationError> errors;

    RoqmeExpressionJson(RoqmeDeclarations declarations, List<GenerationError> errors) {
        this.declarations = declarations;
        this.errors = errors;
    }

    /** The node of e with its "type"; null for null. */
    ObjectNode expr(Expression e) {
        if (e == null) {
            return null;
        }
        ObjectNode node = doSwitch(e);
        node.put("type", type(e));
        return node;
    }

    private static String type(Expression e) {
        if (e instanceof SequenceValue) {
            return "sequence"; // Types gives a sequence its elements' type, for the checks
        }
        return Types.typeOf(e).kind.name().toLowerCase();
    }

    @Override
    public ObjectNode caseBooleanValue(BooleanValue v) {
        return JSON.objectNode().put("boolean", v.isValue());
    }

    @Override
    public ObjectNode caseNumericValue(NumericValue v) {
        return JSON.objectNode().put("number", Numbers.clean(v.getValue()));
    }

    @Override
    public ObjectNode caseTimeValue(TimeValue v) {
        return JSON.objectNode().put("time", Numbers.clean(Evidence.exactMillis(v)));
    }

    @Override
    public ObjectNode caseEventValue(EventValue v) {
        return JSON.objectNode().put("event", true);
    }

    @Override
    public ObjectNode caseStringValue(StringValue v) {
        return JSON.objectNode().put("string", v.getValue());
    }

    @Override
    public ObjectNode caseEnumValue(EnumValue v) {
        EnumLiteral literal = v.getLiteral();
        if (EcoreUtil2.getContainerOfType(literal, VariationPoint.class) != null) {
            return unsupported(v, RoqmeRuntimeModel.VARPOINT, "the RoQME provider does not know varpoint values such as "
                    + Names.literal(literal) + ": only contexts, params, vars, timers and beliefs");
        }
        return JSON.objectNode().put("enum", literal.getName()).put("enumType", Names.enumName(literal.eContainer()));
    }

    @Override
    public ObjectNode caseSequenceValue(SequenceValue v) {
        ObjectNode node = JSON.objectNode();
        ArrayNode values = node.putArray("sequence");
        for (Value value : v.getValues()) {
            values.add(expr(value));
        }
        return node;
    }

    @Override
    public ObjectNode caseVariableRef(VariableRef ref) {
        String id = declarations.id(ref.getVariable());
        if (id == null) {
            return ref.getVariable() instanceof VariationPoint
                    ? unsupported(ref, RoqmeRuntimeModel.VARPOINT, "the RoQME provider does not know varpoint '"
                            + ref.getVariable().getName() + "': observations read contexts, params, vars, timers and beliefs")
                    : unsupported(ref, RoqmeRuntimeModel.REFERENCE, "'" + ref.getVariable().getName()
                            + "' is not declared in this model or a file it imports");
        }
        return JSON.objectNode().put("ref", id);
    }

    @Override
    public ObjectNode caseBeliefExpression(BeliefExpression b) {
        if (b.getBelief() == null) {
            return JSON.objectNode().putNull("belief"); // bare `belief`: the enclosing property
        }
        String id = declarations.id(b.getBelief());
        if (id == null) {
            return unsupported(b, RoqmeRuntimeModel.REFERENCE,
                    "belief '" + b.getBelief().getName() + "' is not declared in this model or a file it imports");
        }
        return JSON.objectNode().put("belief", id);
    }

    @Override
    public ObjectNode caseUnaryExpression(UnaryExpression u) {
        ObjectNode node = JSON.objectNode().put("op", symbol(u.getOperator()));
        node.set("arg", expr(u.getTerm()));
        return node;
    }

    @Override
    public ObjectNode caseBinaryExpression(BinaryExpression b) {
        ObjectNode node = JSON.objectNode().put("op", symbol(b.getOperator()));
        node.set("left", expr(b.getLeft()));
        node.set("right", expr(b.getRight()));
        return node;
    }

    @Override
    public ObjectNode caseConditionalExpression(ConditionalExpression c) {
        ObjectNode node = JSON.objectNode().put("op", "?:");
        node.set("cond", expr(c.getCondition()));
        node.set("then", expr(c.getIfTrue()));
        node.set("else", expr(c.getIfFalse()));
        return node;
    }

    @Override
    public ObjectNode caseWhileExpression(WhileExpression w) {
        ObjectNode node = JSON.objectNode().put("op", "while");
        node.set("arg", expr(w.getTerm()));
        node.set("cond", expr(w.getCondition()));
        return node;
    }

    @Override
    public ObjectNode caseRepeatExpression(RepeatExpression r) {
        ObjectNode node = JSON.objectNode().put("op", "repeat");
        node.set("arg", expr(r.getTerm()));
        node.put("times", r.getTimes());
        return node;
    }

    @Override
    public ObjectNode caseRangeExpression(RangeExpression r) {
        ObjectNode node = JSON.objectNode().put("op", "range");
        node.set("arg", expr(r.getTerm()));
        node.put("min", r.getMin());
        node.put("max", r.getMax());
        return node;
    }

    /** f(a, b) and the postfix a'f(b) alike: the grammar puts the postfix receiver first in args. */
    @Override
    public ObjectNode caseFunctionCall(FunctionCall f) {
        ObjectNode node = JSON.objectNode().put("call", f.getFunction());
        ArrayNode args = node.putArray("args");
        for (Expression arg : f.getArgs()) {
            args.add(expr(arg));
        }
        return node;
    }

    /** An expression class this writer has no case for (a new grammar rule, a MIRoN-only element). */
    @Override
    public ObjectNode defaultCase(EObject e) {
        return unsupported(e, RoqmeRuntimeModel.EXPRESSION,
                "the runtime model cannot represent " + e.eClass().getName() + " expressions yet");
    }

    private ObjectNode unsupported(EObject source, String code, String message) {
        errors.add(new GenerationError(source, message, code));
        return JSON.objectNode(); // never written: the model has an error now
    }

    /** Exhaustive on purpose: a new operator does not compile until it has its JSON name. */
    private static String symbol(BinaryOperator op) {
        return switch (op) {
            case FOLLOWED_BY -> "->";
            case OR -> "or";
            case AND -> "and";
            case LOGICAL_OR -> "|";
            case LOGICAL_AND -> "&";
            case EQ -> "=";
            case NE -> "!=";
            case LT -> "<";
            case GT -> ">";
            case LE -> "<=";
            case GE -> ">=";
            case PLUS -> "+";
            case MINUS -> "-";
            case TIMES -> "*";
            case DIVIDE -> "/";
        };
    }

    private static String symbol(UnaryOperator op) {
        return switch (op) {
            case ONCE -> "once";
            case NOT -> "not";
            case LOGICAL_NOT -> "!";
            case MINUS -> "neg";
        };
    }
}
