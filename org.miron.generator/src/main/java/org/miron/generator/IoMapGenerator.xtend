package org.miron.generator

import org.eclipse.emf.ecore.EObject
import java.util.List
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
 * Writes name.io.json, the generator ⇄ engine contract of docs/io-json.md: every parameter the
 * engine feeds (metrics, contexts and their _known flags; per varpoint _input, _input_value and
 * _current) and every decision it reads, with the MIRoN element, type and binding of each.
 */
class IoMapGenerator {

	def generate(AdaptationModel m) '''
		{
		  "format": 1,
		  "model": «str(m.name)»,
		  "mzn": «str(m.name + ".mzn")»,
		  "dzn": «str(m.name + ".dzn")»,
		  "tree": «if (m.tree === null) "null" else str(m.tree)»,
		  "weights": «str(m.weights.id)»,
		  "inputs": «list(inputs(m))»,
		  "varpoints": «list(m.varpoints.map[vp|varpoint(vp).toString])»
		}
	'''

	/** One entry per line, so that diffs of regenerated maps stay readable. */
	def private list(List<String> entries) {
		if (entries.empty) "[]" else "[\n  " + entries.join(",\n  ") + "\n]" // re-indented by the template
	}

	def private List<String> inputs(AdaptationModel m) {
		(m.properties.map[metric.toString] + m.contexts.map[context.toString]).toList
	}

	def private metric(Property p) '''{ "kind": "metric", "namespace": «str(Names.namespace(p))», "name": «str(p.name)», "param": «str(Names.metric(p))», "type": "float", "initial": «Numbers.json(p.reference ?: 0.5)» }'''

	def private context(Context c) {
		val type = Types.dataType(c as EObject)
		val roqmeType = switch type {
			BooleanType: "boolean"
			EventType: "event"
			EnumType: "enum"
			default: "number"
		}
		val literals = if (type instanceof EnumType) ''', "literals": [«type.literals.map[str(name)].join(", ")»]''' else ""
		'''{ "kind": "context", "namespace": «str(Names.namespace(c))», "name": «str(c.name)», "roqmeType": «str(roqmeType)»«literals», "param": «str(Names.context(c))», "type": «str(ExpressionToMiniZinc.mznType(c))», "known": «str(Names.known(c))» }'''
	}

	def private varpoint(SampledVarpoint vp) {
		val values = if (vp.isEnum) vp.labels.map[str(it)] else vp.values.map[Numbers.json(it)]
		'''{ "name": «str(vp.name)», "kind": «str(if (vp.isEnum) "enum" else "number")», "values": [«values.join(", ")»], "preset": «if (vp.preset < 0) "null" else vp.preset», "decision": «str(vp.decision)», "input": «str(vp.input)», "inputValue": «str(vp.inputValue)», "current": «str(vp.current)», "binding": «binding(vp)» }'''
	}

	def private binding(SampledVarpoint vp) {
		val b = vp.varpoint.binding
		switch b {
			ArchBinding: '''{ "type": "arch", "parameterSetRepository": «str(b.parameterSetRepository)», "parameterSet": «str(b.parameterSet)», "component": «str(b.component)», "parameter": «str(b.parameter)» }'''
			BtBinding: {
				val selected = BindingTargets.select(vp, newArrayList)
				val targets = selected.map[BindingTargets.nameOf(it)].toSet.map[str(it)].join(", ")
				if (vp.isEnum) {
					'''{ "type": "bt", "insertion": «str(b.insertionType.literal)», "targets": [«targets»], "variable": «str(vp.selection)» }'''
				} else {
					val attribute = selected.filter(Attribute).head?.name
					'''{ "type": "btport", "targets": [«targets»], "attribute": «str(attribute)», "variable": «str(vp.name)» }'''
				}
			}
			default: "null"
		}
	}

	/** A JSON string literal (null for null). */
	def static String str(String s) {
		if (s === null) {
			return "null"
		}
		val out = new StringBuilder('"')
		for (c : s.toCharArray) {
			val code = c as int
			if (code == 34 || code == 92) {
				out.append('\\').append(c)
			} else if (code < 32) {
				out.append(String.format("\\u%04x", code))
			} else {
				out.append(c)
			}
		}
		out.append('"').toString
	}
}
