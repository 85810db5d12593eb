package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.dsl.miron.Constraint;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.util.Imports;

/**
 * Analyses a validated MIRoN model (and the .miron files it imports) for the generators: samples
 * its varpoints and translates its rules to MiniZinc. Problems are added to errors.
 */
public class ModelAnalyser {
    private final List<GenerationError> errors;

    public ModelAnalyser(List<GenerationError> errors) {
        this.errors = errors;
    }

    public AdaptationModel analyse(MironModel model, String name, WeightPolicy weights) {
        AdaptationModel m = new AdaptationModel(model, name, weights);
        List<MironModel> models = mironModels(model);
        m.models.addAll(models);

        DataSampler sampler = new DataSampler(errors);
        Map<VariationPoint, SampledVariationPoint> byElement = new LinkedHashMap<>();
        Set<String> names = new HashSet<>();
        for (MironModel each : models) {
            for (VariationPoint vp : filter(each.getVariables(), VariationPoint.class)) {
                if (!names.add(vp.getName())) {
                    errors.add(new GenerationError(vp, "varpoint '" + vp.getName()
                            + "' is declared in two models: MiniZinc names would clash"));
                }
                SampledVariationPoint sampled = sampler.sample(vp);
                if (sampled != null && sampled.preset < 0 && sampled.initial() >= 0) {
                    sampled.preset = sampled.initial(); // the robot's own setting is its nominal value
                }
                if (sampled != null) {
                    byElement.put(vp, sampled);
                    m.varpoints.add(sampled);
                }
            }
        }

        ExpressionToMiniZinc translator = new ExpressionToMiniZinc(byElement, errors);
        ExpressionToTree trees = new ExpressionToTree(byElement, errors);
        for (MironModel each : models) {
            for (Rule rule : filter(each.getSentences(), Rule.class)) {
                m.rules.add(translate(rule, translator, trees));
            }
        }
        RequirementTranslator requirements = new RequirementTranslator(trees, errors);
        for (Requirement requirement : filter(model.getSentences(), Requirement.class)) {
            m.requirements.add(requirements.translate(requirement));
        }
        m.varpoints.forEach(vp -> m.properties.addAll(vp.utilities.keySet()));
        m.properties.addAll(translator.properties);
        m.contexts.addAll(translator.contexts);
        return m;
    }

    private static <T> List<T> filter(List<?> elements, Class<T> type) {
        return elements.stream().filter(type::isInstance).map(type::cast).toList();
    }

    /** The model and the MIRoN models it imports, transitively, each once. */
    private static List<MironModel> mironModels(MironModel model) {
        Set<MironModel> seen = new LinkedHashSet<>();
        Deque<MironModel> pending = new ArrayDeque<>(List.of(model));
        while (!pending.isEmpty()) {
            MironModel next = pending.removeFirst();
            if (seen.add(next)) {
                for (Import imp : next.getImports()) {
                    Resource resource = Imports.load(imp);
                    if (resource != null && !resource.getContents().isEmpty()
                            && resource.getContents().get(0) instanceof MironModel imported) {
                        pending.add(imported);
                    }
                }
            }
        }
        return new ArrayList<>(seen);
    }

    private static AdaptationModel.TranslatedRule translate(Rule rule, ExpressionToMiniZinc translator,
            ExpressionToTree trees) {
        ExpressionToMiniZinc.Mentions guard = new ExpressionToMiniZinc.Mentions();
        boolean always = rule.getCondition() == null || rule.getCondition().getTerm() == null;
        String condition = always ? "true" : translator.translate(rule.getCondition().getTerm(), guard);
        JsonNode conditionTree = always ? JsonNodeFactory.instance.objectNode().put("const", true)
                : trees.translate(rule.getCondition().getTerm());
        List<AdaptationModel.Consequence> consequences = new ArrayList<>();
        Set<Context> contexts = new LinkedHashSet<>(guard.contexts);
        for (Constraint c : rule.getImplies()) {
            ExpressionToMiniZinc.Mentions mentions = new ExpressionToMiniZinc.Mentions();
            consequences.add(new AdaptationModel.Consequence(translator.translate(c.getTerm(), mentions),
                    trees.translate(c.getTerm()), mentions.varpoints));
            contexts.addAll(mentions.contexts);
        }
        String source = Objects.toString(rule.getName(), "") + ": "
                + (rule.getCondition() != null ? text(rule.getCondition()) + " " : "") + "implies "
                + rule.getImplies().stream().map(ModelAnalyser::text).collect(Collectors.joining(", "));
        return new AdaptationModel.TranslatedRule(rule, source, condition, conditionTree, contexts, consequences);
    }

    /** The source text of an element on one line (for comments in the generated model). */
    private static String text(EObject element) {
        ICompositeNode node = NodeModelUtils.findActualNodeFor(element);
        return node == null ? "?" : NodeModelUtils.getTokenText(node);
    }
}
