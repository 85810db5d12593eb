package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.miron.bt.bt.Attribute;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.Binding;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EventType;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.util.Types;

/**
 * Writes name.io.json, the generator ⇄ engine contract of docs/io-json.md (its schema:
 * docs/io-json.schema.json): every parameter the engine feeds (metrics, contexts and their _known
 * flags; per varpoint _input, _input_value and _current) and every decision it reads, with the
 * MIRoN element, type and binding of each. Built as a JSON tree and written by Jackson, the
 * library the engine reads it with.
 */
public class IoMapGenerator {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    public String generate(AdaptationModel m) {
        return IoJsonPrinter.print(tree(m));
    }

    public ObjectNode tree(AdaptationModel m) {
        ObjectNode root = JSON.objectNode();
        root.put("format", 1);
        root.put("model", m.name);
        root.put("mzn", m.name + ".mzn");
        root.put("dzn", m.name + ".dzn");
        root.put("tree", m.tree);
        root.put("weights", m.weights.id());
        ArrayNode inputs = root.putArray("inputs");
        m.properties.forEach(p -> inputs.add(metric(p)));
        m.contexts.forEach(c -> inputs.add(context(c)));
        ArrayNode varpoints = root.putArray("varpoints");
        m.varpoints.forEach(vp -> varpoints.add(varpoint(vp)));
        ArrayNode rules = root.putArray("rules"); // in priority order: the first is the most important
        for (int r = 0; r < m.rules.size(); r++) {
            ObjectNode rule = rules.addObject();
            rule.put("name", m.rules.get(r).rule().getName());
            rule.put("keep", Names.keep(r + 1));
        }
        root.set("decision", decision(m));
        return root;
    }

    /**
     * What the .mzn decides, structured for an in-process solver: utility tables per varpoint (as
     * printed in the .dzn, so both backends weigh the same numbers) and the rules as expression
     * trees with their guards (docs/io-json.md, "decision").
     */
    private static ObjectNode decision(AdaptationModel m) {
        ObjectNode node = JSON.objectNode();
        node.put("objective", m.hasImpacts() ? "maximize" : "satisfy");
        ArrayNode varpoints = node.putArray("varpoints");
        for (SampledVariationPoint vp : m.varpoints) {
            ObjectNode v = varpoints.addObject();
            v.put("name", vp.name);
            ArrayNode utilities = v.putArray("utilities");
            for (Map.Entry<Property, double[]> e : vp.utilities.entrySet()) {
                ObjectNode u = utilities.addObject();
                u.put("metric", Names.metric(e.getKey()));
                ArrayNode table = u.putArray("table");
                for (double utility : e.getValue()) {
                    table.add(new BigDecimal(Numbers.utility(utility)));
                }
            }
        }
        ArrayNode rules = node.putArray("rules");
        for (AdaptationModel.TranslatedRule r : m.rules) {
            ObjectNode rule = rules.addObject();
            rule.put("name", r.rule().getName());
            ArrayNode known = rule.putArray("known");
            r.contexts().forEach(c -> known.add(Names.known(c)));
            rule.set("condition", r.conditionTree());
            ArrayNode consequences = rule.putArray("consequences");
            for (AdaptationModel.Consequence c : r.consequences()) {
                ObjectNode consequence = consequences.addObject();
                ArrayNode overrides = consequence.putArray("overrides");
                c.varpoints().forEach(vp -> overrides.add(vp.name));
                consequence.set("constraint", c.tree());
            }
        }
        return node;
    }

    private static ObjectNode metric(Property p) {
        ObjectNode node = JSON.objectNode();
        node.put("kind", "metric");
        node.put("namespace", Names.namespace(p));
        node.put("name", p.getName());
        node.put("param", Names.metric(p));
        node.put("type", "float");
        node.put("initial", number(Numbers.clean(p.getReference() != null ? p.getReference() : 0.5)));
        return node;
    }

    private static ObjectNode context(Context c) {
        DataType type = Types.dataType((EObject) c);
        ObjectNode node = JSON.objectNode();
        node.put("kind", "context");
        node.put("namespace", Names.namespace(c));
        node.put("name", c.getName());
        roqmeType(node, type);
        node.put("param", Names.context(c));
        node.put("type", ExpressionToMiniZinc.mznType(c));
        node.put("known", Names.known(c));
        return node;
    }

    /** "roqmeType" of a context's type, and its "literals" when it is an enum (also name.requirements.json's). */
    static void roqmeType(ObjectNode node, DataType type) {
        String roqmeType;
        if (type instanceof BooleanType) {
            roqmeType = "boolean";
        } else if (type instanceof EventType) {
            roqmeType = "event";
        } else if (type instanceof EnumType) {
            roqmeType = "enum";
        } else {
            roqmeType = "number";
        }
        node.put("roqmeType", roqmeType);
        if (type instanceof EnumType e) {
            ArrayNode literals = node.putArray("literals");
            for (EnumLiteral literal : e.getLiterals()) {
                literals.add(literal.getName());
            }
        }
    }

    /** A varpoint's "values": its labels, false and true, or its numbers (also name.requirements.json's). */
    static void values(ObjectNode node, SampledVariationPoint vp) {
        ArrayNode values = node.putArray("values");
        if (vp.isEnum()) {
            vp.labels().forEach(values::add);
        } else if (vp.bool) {
            values.add(false).add(true); // the 0/1 of the MiniZinc model, by index
        } else {
            vp.values.forEach(v -> values.add(number(v)));
        }
    }

    private static ObjectNode varpoint(SampledVariationPoint vp) {
        ObjectNode node = JSON.objectNode();
        node.put("name", vp.name);
        node.put("kind", vp.isEnum() ? "enum" : vp.bool ? "boolean" : "number");
        values(node, vp);
        if (vp.preset < 0) {
            node.putNull("preset");
        } else {
            node.put("preset", vp.preset);
        }
        if (vp.initial() < 0) {
            node.putNull("initial");
        } else {
            node.put("initial", vp.initial());
        }
        node.put("decision", vp.decision());
        node.put("input", vp.input());
        node.put("inputValue", vp.inputValue());
        node.put("current", vp.current());
        node.set("binding", binding(vp));
        return node;
    }

    private static JsonNode binding(SampledVariationPoint vp) {
        Binding b = vp.varpoint.getBinding();
        ObjectNode node = JSON.objectNode();
        if (b instanceof ArchBinding arch) {
            node.put("type", "arch");
            node.put("parameterSetRepository", arch.getParameterSetRepository());
            node.put("parameterSet", arch.getParameterSet());
            node.put("component", arch.getComponent());
            node.put("parameter", arch.getParameter());
        } else if (b instanceof BtBinding bt) {
            List<EObject> selected = BindingTargets.select(vp, new ArrayList<>());
            if (vp.isEnum()) {
                node.put("type", "bt");
                node.put("insertion", bt.getInsertionType().getLiteral());
                targets(node, selected);
                node.put("variable", vp.selection());
            } else {
                node.put("type", "btport");
                targets(node, selected);
                node.put("attribute", selected.stream().filter(Attribute.class::isInstance).map(Attribute.class::cast)
                        .findFirst().map(Attribute::getName).orElse(null));
                node.put("variable", vp.name);
            }
        } else {
            return JSON.nullNode();
        }
        return node;
    }

    private static void targets(ObjectNode node, List<EObject> selected) {
        ArrayNode targets = node.putArray("targets");
        Set<String> names = new LinkedHashSet<>();
        selected.forEach(target -> names.add(BindingTargets.nameOf(target)));
        names.forEach(targets::add);
    }

    /** 10, 0.25, -3: no exponent, no trailing zeros (as Numbers.json). */
    static BigDecimal number(BigDecimal value) {
        return value.signum() == 0 ? BigDecimal.ZERO : value.stripTrailingZeros();
    }
}
