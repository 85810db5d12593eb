package org.miron.generator;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.util.Types;

/**
 * Writes name.requirements.json, the generator ⇄ requirement monitor contract of
 * docs/requirements.md (its schema: docs/requirements.schema.json): the signals the requirements
 * read, described so that the monitor needs nothing else, and each requirement with its place, its
 * text and its formula tree. Built as a JSON tree and printed as name.io.json is.
 */
public class RequirementsGenerator {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    public String generate(AdaptationModel m) {
        return IoJsonPrinter.print(tree(m));
    }

    public ObjectNode tree(AdaptationModel m) {
        ObjectNode root = JSON.objectNode();
        root.put("format", 1);
        root.put("model", m.name);
        Map<Variable, String> signals = new LinkedHashMap<>();
        m.requirements.forEach(r -> r.reads().forEach(s -> signals.putIfAbsent(s.variable(), s.name())));
        ArrayNode list = root.putArray("signals");
        signals.forEach((v, name) -> list.add(signal(m, v, name)));
        ArrayNode requirements = root.putArray("requirements");
        m.requirements.forEach(r -> requirements.add(requirement(r)));
        return root;
    }

    private static ObjectNode requirement(AdaptationModel.TranslatedRequirement r) {
        Requirement req = r.requirement();
        ObjectNode node = JSON.objectNode();
        node.put("name", req.getName());
        INode keyword = keyword(req);
        node.put("line", keyword == null ? 0 : keyword.getStartLine());
        node.put("column", keyword == null ? 0 : NodeModelUtils.getLineAndColumn(keyword, keyword.getOffset()).getColumn());
        node.put("text", r.text());
        if (req.getProbability() == null) {
            node.putNull("probability");
        } else {
            node.put("probability", IoMapGenerator.number(BigDecimal.valueOf(req.getProbability())));
        }
        ArrayNode reads = node.putArray("reads");
        r.reads().forEach(s -> reads.add(s.name()));
        node.set("formula", r.formula());
        return node;
    }

    /** The 'requirement' keyword (where the sentence starts after its documentation comment). */
    private static INode keyword(Requirement req) {
        INode node = NodeModelUtils.getNode(req);
        if (node == null) {
            return null;
        }
        for (INode leaf : node.getLeafNodes()) {
            if (leaf.getGrammarElement() instanceof Keyword && "requirement".equals(leaf.getText())) {
                return leaf;
            }
        }
        return node;
    }

    private static ObjectNode signal(AdaptationModel m, Variable v, String name) {
        ObjectNode node = JSON.objectNode();
        node.put("name", name);
        if (v instanceof Property p) {
            node.put("kind", "property");
            node.put("property", p.getName());
            node.put("param", Names.metric(p));
        } else if (v instanceof Context c) {
            DataType type = Types.dataType((EObject) c);
            node.put("kind", "context");
            node.put("context", c.getName());
            IoMapGenerator.roqmeType(node, type);
            node.put("param", Names.context(c));
            if (type instanceof NumericType n && (n.getLower() != null || n.getUpper() != null)) {
                ArrayNode range = node.putArray("range");
                bound(range, n.getLower());
                bound(range, n.getUpper());
            }
        } else if (v instanceof VariationPoint point) {
            SampledVariationPoint vp = m.varpoints.stream().filter(s -> s.varpoint == point).findFirst().orElseThrow();
            node.put("kind", "varpoint");
            node.put("varpoint", vp.name);
            node.put("type", vp.isEnum() ? "enum" : vp.bool ? "boolean" : "number");
            IoMapGenerator.values(node, vp);
            // the value the robot starts with: := v, else an enum's preset (ModelAnalyser folds := v into preset)
            int initial = vp.initial() >= 0 ? vp.initial() : vp.isEnum() ? vp.preset : -1;
            if (initial < 0) {
                node.putNull("initial");
            } else {
                node.put("initial", initial);
            }
        }
        return node;
    }

    private static void bound(ArrayNode range, Double value) {
        if (value == null) {
            range.addNull();
        } else {
            range.add(IoMapGenerator.number(BigDecimal.valueOf(value)));
        }
    }
}
