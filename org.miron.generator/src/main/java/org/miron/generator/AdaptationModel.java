package org.miron.generator;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.Property;

/**
 * A MIRoN model analysed for generation: sampled varpoints, rules already in MiniZinc, and the
 * properties and contexts the generated model reads (its engine-fed parameters).
 */
public final class AdaptationModel {
    /**
     * One consequence of a rule: a constraint on varpoints, guarded by their overrides; in
     * MiniZinc and as the expression tree of the io.json decision section (ExpressionToTree).
     */
    public record Consequence(String constraint, JsonNode tree, Set<SampledVariationPoint> varpoints) {
    }

    /** A rule in MiniZinc, its condition also as an expression tree. */
    public record TranslatedRule(Rule rule, String source, String condition, JsonNode conditionTree,
            Set<Context> contexts, List<Consequence> consequences) {
    }

    /** A signal a requirement reads: a context, a property or a varpoint, named as the model writes it. */
    public record Signal(String name, org.miron.dsl.roqme.Variable variable) {
    }

    /** A requirement: its formula's source text, its formula tree (docs/requirements.md) and its signals in order of first use. */
    public record TranslatedRequirement(org.miron.dsl.miron.Requirement requirement, String text, JsonNode formula,
            List<Signal> reads) {
    }

    public final MironModel model;
    /** The model and the MIRoN models it imports (their varpoints and rules are generated too). */
    public final List<MironModel> models = new ArrayList<>();
    /** Base name of the outputs: name.mzn, name.dzn, name.io.json, name.ext.xml. */
    public final String name;
    public final WeightPolicy weights;
    public final List<SampledVariationPoint> varpoints = new ArrayList<>();
    public final List<TranslatedRule> rules = new ArrayList<>();
    /** The requirements of the model itself, in declaration order (an imported model's are its own). */
    public final List<TranslatedRequirement> requirements = new ArrayList<>();
    public final Set<Property> properties = new LinkedHashSet<>();
    public final Set<Context> contexts = new LinkedHashSet<>();
    /** File name of the woven tree, or null when the model weaves no behaviour tree. */
    public String tree;

    public AdaptationModel(MironModel model, String name, WeightPolicy weights) {
        this.model = model;
        this.name = name;
        this.weights = weights;
    }

    /** True when some varpoint declares an impact: the model optimises, else it only satisfies. */
    public boolean hasImpacts() {
        return varpoints.stream().anyMatch(vp -> !vp.utilities.isEmpty());
    }
}
