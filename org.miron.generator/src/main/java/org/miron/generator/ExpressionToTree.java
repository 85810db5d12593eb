package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.miron.VariationPoint;
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
import org.miron.dsl.util.Types;

/**
 * The rule expressions of {@link ExpressionToMiniZinc} as JSON trees (the io.json {@code decision}
 * section, read by the engine's native backend). Node for node the same expression as the
 * MiniZinc text, so both backends decide the same: {@code {"const": 0.3}}, {@code {"param":
 * "metric_..."}}, {@code {"index": "vp"}} (the decision), {@code {"value": "vp"}} (its value
 * {@code vp_x[vp_var]}), {@code {"op": "<", "args": [...]}}. Errors are reported by
 * ExpressionToMiniZinc; what it refuses becomes {@code {"const": false}} here.
 */
final class ExpressionToTree {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;
    private final Map<VariationPoint, SampledVarpoint> varpoints;

    ExpressionToTree(Map<VariationPoint, SampledVarpoint> varpoints) {
        this.varpoints = varpoints;
    }

    JsonNode translate(Expression e) {
        if (e instanceof BinaryExpression b) {
            return binary(b);
        } else if (e instanceof UnaryExpression u) {
            return switch (u.getOperator()) {
                case NOT, LOGICAL_NOT -> op("not", translate(u.getTerm()));
                case MINUS -> op("neg", translate(u.getTerm()));
                default -> constant(false);
            };
        } else if (e instanceof ConditionalExpression c) {
            return op("if", translate(c.getCondition()), translate(c.getIfTrue()), translate(c.getIfFalse()));
        } else if (e instanceof VariableRef r) {
            return reference(r);
        } else if (e instanceof BeliefExpression b) {
            return b.getBelief() instanceof Property p ? param(Names.metric(p)) : constant(false);
        } else if (e instanceof NumericValue n) {
            return JSON.objectNode().set("const", JSON.numberNode(new BigDecimal(Numbers.mzn(n.getValue()))));
        } else if (e instanceof BooleanValue b) {
            return constant(b.isValue());
        } else if (e instanceof EventValue) {
            return constant(true);
        } else if (e instanceof EnumValue v) {
            EObject type = v.getLiteral() == null ? null : v.getLiteral().eContainer();
            return type instanceof EnumType t ? JSON.objectNode().put("const", t.getLiterals().indexOf(v.getLiteral()))
                    : constant(false);
        } else if (e instanceof FunctionCall f) {
            ObjectNode node = JSON.objectNode().put("op", f.getFunction());
            ArrayNode args = node.putArray("args");
            f.getArgs().forEach(a -> args.add(translate(a)));
            return node;
        }
        return constant(false);
    }

    private JsonNode binary(BinaryExpression e) {
        BinaryOperator op = e.getOperator();
        if (op == BinaryOperator.EQ || op == BinaryOperator.NE) {
            SampledVarpoint vp = numericVarpoint(e.getLeft());
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
        return symbol == null ? constant(false) : op(symbol, translate(e.getLeft()), translate(e.getRight()));
    }

    private JsonNode reference(VariableRef e) {
        Object v = e.getVariable();
        if (v instanceof Property p) {
            return param(Names.metric(p));
        } else if (v instanceof Context c) {
            return param(Names.context(c));
        } else if (v instanceof VariationPoint point) {
            SampledVarpoint vp = varpoints.get(point);
            if (vp == null) {
                return constant(false);
            }
            if (vp.isEnum()) {
                return JSON.objectNode().put("index", vp.name);
            }
            if (Types.dataType((EObject) point) instanceof BooleanType) {
                return op("=", JSON.objectNode().put("index", vp.name), JSON.objectNode().put("const", 1));
            }
            return value(vp);
        } else if (v instanceof Param p) {
            return p.getInitializedTo() == null ? constant(false) : translate(p.getInitializedTo());
        }
        return constant(false);
    }

    private SampledVarpoint numericVarpoint(Expression e) {
        if (e instanceof VariableRef r && r.getVariable() instanceof VariationPoint point) {
            SampledVarpoint vp = varpoints.get(point);
            if (vp != null && !vp.isEnum() && Types.dataType((EObject) point) instanceof NumericType) {
                return vp;
            }
        }
        return null;
    }

    private static JsonNode value(SampledVarpoint vp) {
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
