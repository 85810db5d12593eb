package org.miron.generator

import com.fasterxml.jackson.databind.node.JsonNodeFactory
import java.util.LinkedHashMap
import java.util.LinkedHashSet
import java.util.List
import org.eclipse.emf.ecore.EObject
import org.eclipse.xtext.nodemodel.util.NodeModelUtils
import org.miron.dsl.miron.MironModel
import org.miron.dsl.miron.Rule
import org.miron.dsl.miron.VariationPoint
import org.miron.dsl.util.Imports

/**
 * Analyses a validated MIRoN model (and the .miron files it imports) for the generators: samples
 * its varpoints and translates its rules to MiniZinc. Problems are added to errors.
 */
class ModelAnalyser {
	val List<GenerationError> errors

	new(List<GenerationError> errors) {
		this.errors = errors
	}

	def AdaptationModel analyse(MironModel model, String name, WeightPolicy weights) {
		val m = new AdaptationModel(model, name, weights)
		val models = mironModels(model)
		m.models += models

		val sampler = new DataSampler(errors)
		val byElement = new LinkedHashMap<VariationPoint, SampledVarpoint>
		val names = newHashSet
		for (vp : models.map[variables.filter(VariationPoint)].flatten) {
			if (!names.add(vp.name)) {
				errors += new GenerationError(vp, '''varpoint '«vp.name»' is declared in two models: MiniZinc names would clash''')
			}
			val sampled = sampler.sample(vp)
			if (sampled !== null) {
				byElement.put(vp, sampled)
				m.varpoints += sampled
			}
		}

		val translator = new ExpressionToMiniZinc(byElement, errors)
		val trees = new ExpressionToTree(byElement)
		for (rule : models.map[sentences.filter(Rule)].flatten) {
			m.rules += translate(rule, translator, trees)
		}
		m.varpoints.forEach[m.properties += utilities.keySet]
		m.properties += translator.properties
		m.contexts += translator.contexts
		m
	}

	/** The model and the MIRoN models it imports, transitively, each once. */
	def private mironModels(MironModel model) {
		val seen = new LinkedHashSet<MironModel>
		val pending = newLinkedList(model)
		while (!pending.empty) {
			val next = pending.removeFirst
			if (seen.add(next)) {
				for (imp : next.imports) {
					val root = Imports.load(imp)?.contents?.head
					if (root instanceof MironModel) {
						pending += root
					}
				}
			}
		}
		seen.toList
	}

	def private translate(Rule rule, ExpressionToMiniZinc translator, ExpressionToTree trees) {
		val guard = new ExpressionToMiniZinc.Mentions
		val condition = if (rule.condition?.term === null) "true" else translator.translate(rule.condition.term, guard)
		val conditionTree = if (rule.condition?.term === null) JsonNodeFactory.instance.objectNode.put("const", true) else trees.translate(rule.condition.term)
		val consequences = <AdaptationModel.Consequence>newArrayList
		val contexts = new LinkedHashSet(guard.contexts)
		for (c : rule.implies) {
			val mentions = new ExpressionToMiniZinc.Mentions
			consequences += new AdaptationModel.Consequence(translator.translate(c.term, mentions), trees.translate(c.term), mentions.varpoints)
			contexts += mentions.contexts
		}
		val source = '''«rule.name»: «IF rule.condition !== null»«text(rule.condition)» «ENDIF»implies «rule.implies.map[text(it)].join(", ")»'''
		new AdaptationModel.TranslatedRule(rule, source, condition, conditionTree, contexts, consequences)
	}

	/** The source text of an element on one line (for comments in the generated model). */
	def private static text(EObject element) {
		val node = NodeModelUtils.findActualNodeFor(element)
		if (node === null) "?" else NodeModelUtils.getTokenText(node)
	}
}
