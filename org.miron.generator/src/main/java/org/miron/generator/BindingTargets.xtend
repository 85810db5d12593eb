package org.miron.generator

import java.util.List
import org.eclipse.emf.ecore.EObject
import org.miron.bt.bt.Attribute
import org.miron.bt.bt.SubtreeNode
import org.miron.bt.bt.TreeNode
import org.miron.bt.util.BtAttributes
import org.miron.dsl.bt.BtXPath
import org.miron.dsl.miron.BehaviorTreeLiteral
import org.miron.dsl.miron.BtBinding

/** What a varpoint's BT binding points at: tree nodes, or node attributes (ports). */
class BindingTargets {
	/** The tree nodes or attributes a BT binding selects (its XPath is applied to each target). */
	def static List<EObject> select(SampledVarpoint vp, List<GenerationError> errors) {
		val binding = vp.varpoint.binding as BtBinding
		val result = <EObject>newArrayList
		for (target : binding.targets.filter[!eIsProxy]) {
			if (binding.xpath === null) {
				result += target
			} else {
				val selection = BtXPath.evaluate(binding.xpath, target)
				if (selection.error !== null) {
					errors += new GenerationError(binding, selection.error)
				}
				result += selection.selections.map[model].filterNull.filter[it instanceof TreeNode || it instanceof Attribute]
			}
		}
		if (!vp.isEnum && result.exists[it instanceof TreeNode]) {
			errors += new GenerationError(binding, '''numeric varpoint '«vp.name»' can only be bound to node attributes (ports), e.g. in "@speed" «binding.targets.head?.name»''')
		}
		if (vp.isEnum && result.exists[it instanceof TreeNode] && !vp.literals.forall[it instanceof BehaviorTreeLiteral]) {
			errors += new GenerationError(binding, '''enum varpoint '«vp.name»' is bound to a tree node, so each literal must name a behavior tree or be the preset''')
		}
		result
	}


	/** How a node is named in the IO map: its name, else its ID, else its tag. */
	def static String nameOf(EObject target) {
		switch target {
			Attribute: nameOf(target.eContainer)
			SubtreeNode: BtAttributes.value(target.attributes, "name") ?: target.behaviorTree?.name ?: target.tag
			TreeNode: BtAttributes.value(target.attributes, "name") ?: BtAttributes.value(target.attributes, "ID") ?: target.tag
			default: "?"
		}
	}
}
