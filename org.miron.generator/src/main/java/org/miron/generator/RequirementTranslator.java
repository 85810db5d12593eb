package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.miron.Implication;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.util.Evidence;
import org.miron.dsl.util.Formulas;

/**
 * A requirement's formula as the formula tree of name.requirements.json (docs/requirements.md):
 * temporal operators, implies and the connectives above state formulas, each state formula
 * translated by {@link ExpressionToTree} (the engine's expression language) with the signals it reads.
 */
final class RequirementTranslator {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;
    private final ExpressionToTree trees;
    private final List<GenerationError> errors;

    RequirementTranslator(ExpressionToTree trees, List<GenerationError> errors) {
        this.trees = trees;
        this.errors = errors;
    }

    AdaptationModel.TranslatedRequirement translate(Requirement r) {
        Map<Variable, String> reads = new LinkedHashMap<>();
        JsonNode formula = formula(r.getFormula(), reads);
        List<AdaptationModel.Signal> signals = new ArrayList<>();
        reads.forEach((v, name) -> signals.add(new AdaptationModel.Signal(name, v)));
        return new AdaptationModel.TranslatedRequirement(r, Formulas.text(r.getFormula()), formula, signals);
    }

    /** The formula node of e; the signals it reads are added to reads (in order of first use). */
    private JsonNode formula(Expression e, Map<Variable, String> reads) {
        if (e != null && Formulas.isState(e)) {
            Map<Variable, String> own = signals(e);
            own.forEach(reads::putIfAbsent);
            ObjectNode node = JSON.objectNode();
            node.set("state", trees.translate(e));
            ArrayNode names = node.putArray("reads");
            own.values().forEach(names::add);
            return node;
        } else if (e instanceof TemporalExpression t) {
            ObjectNode node = JSON.objectNode().put("op", t.getOperator().getLiteral());
            if (t.getBound() != null) {
                node.put("within", Evidence.millis(t.getBound()));
            }
            return args(node, formula(t.getTerm(), reads));
        } else if (e instanceof Implication i) {
            return args(JSON.objectNode().put("op", "implies"), formula(i.getLeft(), reads), formula(i.getRight(), reads));
        } else if (e instanceof UnaryExpression u && Formulas.isConnective(u)) {
            return args(JSON.objectNode().put("op", "not"), formula(u.getTerm(), reads));
        } else if (e instanceof BinaryExpression b && Formulas.isConnective(b)) {
            String op = switch (b.getOperator()) {
                case OR, LOGICAL_OR -> "or";
                default -> "and";
            };
            return args(JSON.objectNode().put("op", op), formula(b.getLeft(), reads), formula(b.getRight(), reads));
        }
        // refused by the validator (miron.requirement-type): never written
        errors.add(new GenerationError(e, "cannot generate the requirement formula '" + Formulas.text(e)
                + "': only not, and, or and implies combine temporal formulas"));
        return JSON.objectNode().set("state", JSON.objectNode().put("const", false));
    }

    private static ObjectNode args(ObjectNode node, JsonNode... args) {
        ArrayNode a = node.putArray("args");
        for (JsonNode arg : args) {
            a.add(arg);
        }
        return node;
    }

    /** The contexts, properties and varpoints e reads, in order of first use, each by its name as written. */
    private static Map<Variable, String> signals(Expression e) {
        List<VariableRef> refs = new ArrayList<>();
        if (e instanceof VariableRef ref) {
            refs.add(ref);
        }
        refs.addAll(EcoreUtil2.getAllContentsOfType(e, VariableRef.class));
        Map<Variable, String> signals = new LinkedHashMap<>();
        for (VariableRef ref : refs) {
            Variable v = ref.getVariable();
            if (v instanceof Context || v instanceof Property || v instanceof VariationPoint) {
                signals.putIfAbsent(v, written(ref));
            }
        }
        return signals;
    }

    private static String written(VariableRef ref) {
        List<INode> nodes = NodeModelUtils.findNodesForFeature(ref, RoqmePackage.Literals.VARIABLE_REF__VARIABLE);
        return nodes.isEmpty() ? ref.getVariable().getName() : NodeModelUtils.getTokenText(nodes.get(0)).replace(" ", "");
    }
}
