package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.ComposedSwitch;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.miron.util.MironSwitch;
import org.miron.dsl.roqme.BeliefExpression;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.BooleanValue;
import org.miron.dsl.roqme.ConditionalExpression;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.EventValue;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.Param;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.roqme.util.RoqmeSwitch;
import org.miron.dsl.util.Types;

/**
 * The rule expressions of {@link ExpressionToMiniZinc} as JSON trees (the io.json {@code decision}
 * section, read by the engine's native backend). Node for node the same expression as the
 * MiniZinc text, so both backends decide the same: {@code {"const": 0.3}}, {@code {"param":
 * "metric_..."}}, {@code {"index": "vp"}} (the decision), {@code {"value": "vp"}} (its value
 * {@code vp_x[vp_var]}), {@code {"op": "<", "args": [...]}}. Expressions dispatch on EMF's
 * generated switches, as in ExpressionToMiniZinc. What ExpressionToMiniZinc refuses (and reports)
 * becomes {@code {"const": false}} here; what only this class cannot translate (a case added there
 * and forgotten here) is reported too, so the two never silently disagree.
 */
final class ExpressionToTree {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;
    private final Map<VariationPoint, SampledVariationPoint> varpoints;
    private final List<GenerationError> errors;

    /** Expressions by class; a class without a case reaches defaultCase, which reports it. */
    private final RoqmeSwitch<JsonNode> expressions = new RoqmeSwitch<>() {
        @Override
        public JsonNode caseBinaryExpression(BinaryExpression e) {
            return binary(e);
        }

        @Override
        public JsonNode caseUnaryExpression(UnaryExpression u) {
            return switch (u.getOperator()) {
                case NOT, LOGICAL_NOT -> op("not", translate(u.getTerm()));
                case MINUS -> op("neg", translate(u.getTerm()));
                default -> unsupported(u);
            };
        }

        @Override
        public JsonNode caseConditionalExpression(ConditionalExpression c) {
            return op("if", translate(c.getCondition()), translate(c.getIfTrue()), translate(c.getIfFalse()));
        }

        @Override
        public JsonNode caseVariableRef(VariableRef r) {
            JsonNode read = r.getVariable() == null ? null : variables.doSwitch(r.getVariable());
            return read != null ? read : unsupported(r);
        }

        @Override
        public JsonNode caseBeliefExpression(BeliefExpression b) {
            return b.getBelief() instanceof Property p ? param(Names.metric(p)) : unsupported(b);
        }

        @Override
        public JsonNode caseNumericValue(NumericValue n) {
            return JSON.objectNode().set("const", JSON.numberNode(new BigDecimal(Numbers.mzn(n.getValue()))));
        }

        @Override
        public JsonNode caseBooleanValue(BooleanValue b) {
            return constant(b.isValue());
        }

        @Override
        public JsonNode caseEventValue(EventValue e) {
            return constant(true);
        }

        @Override
        public JsonNode caseEnumValue(EnumValue v) {
            EObject type = v.getLiteral() == null ? null : v.getLiteral().eContainer();
            return type instanceof EnumType t ? JSON.objectNode().put("const", t.getLiterals().indexOf(v.getLiteral()))
                    : unsupported(v);
        }

        @Override
        public JsonNode caseFunctionCall(FunctionCall f) {
            if (arity(f.getFunction()) != f.getArgs().size()) {
                return unsupported(f);
            }
            ObjectNode node = JSON.objectNode().put("op", f.getFunction());
            ArrayNode args = node.putArray("args");
            f.getArgs().forEach(a -> args.add(translate(a)));
            return node;
        }

        @Override
        public JsonNode defaultCase(EObject e) {
            return unsupported(e);
        }
    };

    /**
     * The variable a reference reads: RoQME's properties, contexts and params, MIRoN's varpoints.
     * Null (a variable that has no value here) falls through to the reference, which reports it.
     */
    private final ComposedSwitch<JsonNode> variables = new ComposedSwitch<>(List.of(new RoqmeSwitch<JsonNode>() {
        @Override
        public JsonNode caseProperty(Property p) {
            return param(Names.metric(p));
        }

        @Override
        public JsonNode caseContext(Context c) {
            return param(Names.context(c));
        }

        @Override
        public JsonNode caseParam(Param p) {
            return p.getInitializedTo() == null ? null : translate(p.getInitializedTo());
        }
    }, new MironSwitch<JsonNode>() {
        @Override
        public JsonNode caseVariationPoint(VariationPoint point) {
            SampledVariationPoint vp = varpoints.get(point);
            if (vp == null) {
                return null;
            }
            if (vp.isEnum()) {
                return JSON.objectNode().put("index", vp.name);
            }
            if (Types.dataType((EObject) point) instanceof BooleanType) {
                return op("=", JSON.objectNode().put("index", vp.name), JSON.objectNode().put("const", 1));
            }
            return value(vp);
        }
    }));

    /** Errors are added to errors (those ExpressionToMiniZinc reported first are not repeated). */
    ExpressionToTree(Map<VariationPoint, SampledVariationPoint> varpoints, List<GenerationError> errors) {
        this.varpoints = varpoints;
        this.errors = errors;
    }

    JsonNode translate(Expression e) {
        return e == null ? unsupported(null) : expressions.doSwitch(e);
    }

    private JsonNode binary(BinaryExpression e) {
        BinaryOperator op = e.getOperator();
        if (op == BinaryOperator.EQ || op == BinaryOperator.NE) {
            SampledVariationPoint vp = numericVarpoint(e.getLeft());
            Expression other = e.getRight();
            if (vp == null) {
                vp = numericVarpoint(e.getRight());
                other = e.getLeft();
            }
            if (vp != null) { // within half a step, as ExpressionToMiniZinc
                JsonNode distance = op("abs", op("-", value(vp), translate(other)));
                JsonNode half = JSON.objectNode().set("const",
                        JSON.numberNode(new BigDecimal(Numbers.mzn(vp.step.doubleValue() / 2))));
                return op(op == BinaryOperator.EQ ? "<=" : ">", distance, half);
            }
        }
        String symbol = switch (op) {
            case OR, LOGICAL_OR -> "or";
            case AND, LOGICAL_AND -> "and";
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
            default -> null;
        };
        return symbol == null ? unsupported(e) : op(symbol, translate(e.getLeft()), translate(e.getRight()));
    }

    /** The number of arguments of a function rules may call (as ExpressionToMiniZinc), -1 for others. */
    private static int arity(String function) {
        return switch (function == null ? "" : function) {
            case "abs", "sqrt", "exp" -> 1;
            case "pow", "min", "max" -> 2;
            default -> -1;
        };
    }

    private SampledVariationPoint numericVarpoint(Expression e) {
        if (e instanceof VariableRef r && r.getVariable() instanceof VariationPoint point) {
            SampledVariationPoint vp = varpoints.get(point);
            if (vp != null && !vp.isEnum() && Types.dataType((EObject) point) instanceof NumericType) {
                return vp;
            }
        }
        return null;
    }

    /**
     * {"const": false} for an element without a tree; reported unless ExpressionToMiniZinc already
     * reported it (then generation fails on that error and this tree is never written).
     */
    private JsonNode unsupported(EObject e) {
        if (errors.stream().noneMatch(error -> error.source() == e)) {
            ICompositeNode node = e == null ? null : NodeModelUtils.findActualNodeFor(e);
            String text = node == null ? "" : NodeModelUtils.getTokenText(node);
            errors.add(new GenerationError(e, "cannot generate the decision tree for '" + text + "': "
                    + (e == null ? "nothing" : e.eClass().getName()) + " has no case in ExpressionToTree"));
        }
        return constant(false);
    }

    private static JsonNode value(SampledVariationPoint vp) {
        return JSON.objectNode().put("value", vp.name);
    }

    private static JsonNode param(String name) {
        return JSON.objectNode().put("param", name);
    }

    private static JsonNode constant(boolean b) {
        return JSON.objectNode().put("const", b);
    }

    private static JsonNode op(String op, JsonNode... args) {
        ObjectNode node = JSON.objectNode().put("op", op);
        ArrayNode a = node.putArray("args");
        for (JsonNode arg : args) {
            a.add(arg);
        }
        return node;
    }
}
