package org.miron.generator

import com.fasterxml.jackson.core.JsonGenerator
import com.fasterxml.jackson.databind.JsonNode
import com.fasterxml.jackson.databind.ObjectMapper
import com.fasterxml.jackson.databind.node.JsonNodeFactory
import com.fasterxml.jackson.databind.node.ObjectNode
import java.math.BigDecimal
import org.eclipse.emf.ecore.EObject
import org.miron.bt.bt.Attribute
import org.miron.dsl.miron.ArchBinding
import org.miron.dsl.miron.BtBinding
import org.miron.dsl.roqme.BooleanType
import org.miron.dsl.roqme.Context
import org.miron.dsl.roqme.EnumType
import org.miron.dsl.roqme.EventType
import org.miron.dsl.roqme.Property
import org.miron.dsl.util.Types

/**
 * Writes name.io.json, the generator ⇄ engine contract of docs/io-json.md (its schema:
 * docs/io-json.schema.json): every parameter the engine feeds (metrics, contexts and their _known
 * flags; per varpoint _input, _input_value and _current) and every decision it reads, with the
 * MIRoN element, type and binding of each. Built as a JSON tree and written by Jackson, the
 * library the engine reads it with.
 */
class IoMapGenerator {
	static val json = JsonNodeFactory.instance
	static val mapper = new ObjectMapper().enable(JsonGenerator.Feature.WRITE_BIGDECIMAL_AS_PLAIN)

	def String generate(AdaptationModel m) {
		mapper.writer(new IoJsonPrinter).writeValueAsString(tree(m)) + "\n"
	}

	def ObjectNode tree(AdaptationModel m) {
		val root = json.objectNode
		root.put("format", 1)
		root.put("model", m.name)
		root.put("mzn", m.name + ".mzn")
		root.put("dzn", m.name + ".dzn")
		root.put("tree", m.tree)
		root.put("weights", m.weights.id)
		val inputs = root.putArray("inputs")
		m.properties.forEach[inputs.add(metric(it))]
		m.contexts.forEach[inputs.add(context(it))]
		val varpoints = root.putArray("varpoints")
		m.varpoints.forEach[varpoints.add(varpoint(it))]
		root.set("decision", decision(m))
		root
	}

	/**
	 * What the .mzn decides, structured for an in-process solver: utility tables per varpoint (as
	 * printed in the .dzn, so both backends weigh the same numbers) and the rules as expression
	 * trees with their guards (docs/io-json.md, "decision").
	 */
	def private decision(AdaptationModel m) {
		val node = json.objectNode
		node.put("objective", if (m.hasImpacts) "maximize" else "satisfy")
		val varpoints = node.putArray("varpoints")
		for (vp : m.varpoints) {
			val v = varpoints.addObject
			v.put("name", vp.name)
			val utilities = v.putArray("utilities")
			for (e : vp.utilities.entrySet) {
				val u = utilities.addObject
				u.put("metric", Names.metric(e.key))
				val table = u.putArray("table")
				e.value.forEach[table.add(new BigDecimal(Numbers.utility(it)))]
			}
		}
		val rules = node.putArray("rules")
		for (r : m.rules) {
			val rule = rules.addObject
			rule.put("name", r.rule.name)
			val known = rule.putArray("known")
			r.contexts.forEach[known.add(Names.known(it))]
			rule.set("condition", r.conditionTree)
			val consequences = rule.putArray("consequences")
			for (c : r.consequences) {
				val consequence = consequences.addObject
				val overrides = consequence.putArray("overrides")
				c.varpoints.forEach[overrides.add(name)]
				consequence.set("constraint", c.tree)
			}
		}
		node
	}

	def private metric(Property p) {
		val node = json.objectNode
		node.put("kind", "metric")
		node.put("namespace", Names.namespace(p))
		node.put("name", p.name)
		node.put("param", Names.metric(p))
		node.put("type", "float")
		node.put("initial", number(Numbers.clean(p.reference ?: 0.5)))
		node
	}

	def private context(Context c) {
		val type = Types.dataType(c as EObject)
		val node = json.objectNode
		node.put("kind", "context")
		node.put("namespace", Names.namespace(c))
		node.put("name", c.name)
		node.put("roqmeType", switch type {
			BooleanType: "boolean"
			EventType: "event"
			EnumType: "enum"
			default: "number"
		})
		if (type instanceof EnumType) {
			val literals = node.putArray("literals")
			type.literals.forEach[literals.add(name)]
		}
		node.put("param", Names.context(c))
		node.put("type", ExpressionToMiniZinc.mznType(c))
		node.put("known", Names.known(c))
		node
	}

	def private varpoint(SampledVarpoint vp) {
		val node = json.objectNode
		node.put("name", vp.name)
		node.put("kind", if (vp.isEnum) "enum" else "number")
		val values = node.putArray("values")
		if (vp.isEnum) vp.labels.forEach[values.add(it)] else vp.values.forEach[values.add(number(it))]
		if (vp.preset < 0) node.putNull("preset") else node.put("preset", vp.preset)
		node.put("decision", vp.decision)
		node.put("input", vp.input)
		node.put("inputValue", vp.inputValue)
		node.put("current", vp.current)
		node.set("binding", binding(vp))
		node
	}

	def private JsonNode binding(SampledVarpoint vp) {
		val b = vp.varpoint.binding
		val node = json.objectNode
		switch b {
			ArchBinding: {
				node.put("type", "arch")
				node.put("parameterSetRepository", b.parameterSetRepository)
				node.put("parameterSet", b.parameterSet)
				node.put("component", b.component)
				node.put("parameter", b.parameter)
			}
			BtBinding: {
				val selected = BindingTargets.select(vp, newArrayList)
				if (vp.isEnum) {
					node.put("type", "bt")
					node.put("insertion", b.insertionType.literal)
					targets(node, selected)
					node.put("variable", vp.selection)
				} else {
					node.put("type", "btport")
					targets(node, selected)
					node.put("attribute", selected.filter(Attribute).head?.name)
					node.put("variable", vp.name)
				}
			}
			default: return json.nullNode
		}
		node
	}

	def private targets(ObjectNode node, Iterable<EObject> selected) {
		val targets = node.putArray("targets")
		selected.map[BindingTargets.nameOf(it)].toSet.forEach[targets.add(it)]
	}

	/** 10, 0.25, -3: no exponent, no trailing zeros (as Numbers.json). */
	def private static number(BigDecimal value) {
		if (value.signum == 0) BigDecimal.ZERO else value.stripTrailingZeros
	}
}
