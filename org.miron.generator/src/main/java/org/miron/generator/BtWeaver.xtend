package org.miron.generator

import java.util.ArrayDeque
import java.util.LinkedHashMap
import java.util.LinkedHashSet
import java.util.List
import java.util.Map
import java.util.Set
import org.eclipse.emf.common.util.URI
import org.eclipse.emf.ecore.EObject
import org.eclipse.emf.ecore.resource.Resource
import org.eclipse.emf.ecore.util.EcoreUtil
import org.eclipse.xtext.EcoreUtil2
import org.miron.bt.bt.Attribute
import org.miron.bt.bt.BTModel
import org.miron.bt.bt.BehaviorTree
import org.miron.bt.bt.BtFactory
import org.miron.bt.bt.ControlNode
import org.miron.bt.bt.SubtreeNode
import org.miron.bt.bt.SubtreePlus
import org.miron.bt.bt.Switch
import org.miron.bt.bt.TreeNode
import org.miron.bt.scoping.BtGlobalScopeProvider
import org.miron.bt.util.BtTrees
import org.miron.bt.util.BtFormats
import org.miron.bt.formats.BtFormatConverter
import org.miron.dsl.miron.BehaviorTreeLiteral
import org.miron.dsl.miron.BtBinding
import org.miron.dsl.miron.InsertionType
import org.miron.dsl.util.Imports

/**
 * Weaves the variation points bound to behaviour-tree nodes into a copy of the nominal tree
 * (docs/generators.md, "The woven behaviour tree"):
 *  - an enum varpoint becomes a Switch over {vp_sel} with one SubTreePlus per non-preset literal
 *    and a default child: the original target for `in`, AlwaysSuccess for `before`/`after`;
 *    when `in` replaces a subtree call, each variant gets that call's port wiring (its attributes
 *    but name), so a variant sees the same inputs as the nominal subtree;
 *    BehaviorTree.CPP 3 stops at Switch6, so more cases nest Switches through the default child;
 *  - `before`/`after` insert the Switch next to the target in its parent; where the parent takes
 *    exactly one child or counts its children (a tree, a decorator, a Switch) target and Switch
 *    are wrapped in a Sequence instead, which keeps the tree loadable and the cases aligned;
 *  - a numeric varpoint bound to an attribute replaces its value by the port {vp};
 *  - the keys the runtime writes into the main tree's blackboard ({vp_sel}, {vp}) are remapped on
 *    every subtree call between the main tree and the subtree that reads them;
 *  - the main tree's root is wrapped once in the monitoring Parallel whose Repeat ticks one
 *    VariantAction per enum varpoint.
 * Trees of other files stay there and are reached through includes relative to the woven tree
 * (computed on URIs); only the files holding targets are copied into the woven tree.
 * The woven tree is written for BehaviorTree.CPP 3 or 4 (by default the version of the imported
 * tree): copied trees of the other version are converted (BtFormatConverter), and what the weaver
 * adds uses the version's idioms (v3: SubTreePlus, success_threshold; v4: SubTree with {key}
 * remapping and _autoremap, success_count).
 */
class BtWeaver {
	/** BehaviorTree.CPP 3 registers Switch2..Switch6 only. */
	public static val MAX_CASES = 6

	val List<GenerationError> errors
	/** Where the woven tree will be written: includes are relative to it. */
	val URI wovenTree
	val factory = BtFactory.eINSTANCE
	/** Originals to their copies in the woven tree: variant calls point at the copies when there are. */
	var EcoreUtil.Copier copier
	/** The requested BehaviorTree.CPP format, or null for the imported tree's. */
	val Integer requestedFormat
	/** The format being written, 3 or 4. */
	var int format

	new(List<GenerationError> errors, URI wovenTree) {
		this(errors, wovenTree, null)
	}

	new(List<GenerationError> errors, URI wovenTree, Integer format) {
		this.errors = errors
		this.wovenTree = wovenTree
		this.requestedFormat = format
	}

	/** The woven tree, or null when the model imports no behaviour tree. */
	def BTModel weave(AdaptationModel m) {
		val btFiles = m.models.map[imports].flatten.map[imp|Imports.load(imp)].filterNull
			.filter[contents.head instanceof BTModel].toSet.toList
		val bound = m.varpoints.filter[varpoint.binding instanceof BtBinding].toList
		if (btFiles.empty) {
			return null // nothing to weave into; BT bindings without a .bt import are validation errors
		}
		// The nominal tree: the imported .bt that names a main tree, else the first one.
		val primary = btFiles.findFirst[(contents.head as BTModel).main_tree_to_execute !== null] ?: btFiles.head
		val targets = new LinkedHashMap<SampledVarpoint, List<EObject>>
		val woven = new LinkedHashSet<Resource>
		woven += primary
		for (vp : bound) {
			val selected = BindingTargets.select(vp, errors)
			targets.put(vp, selected)
			selected.forEach[woven += eResource]
		}
		copier = new EcoreUtil.Copier
		val copies = woven.map[copier.copy(contents.head) as BTModel].toList
		copier.copyReferences
		format = requestedFormat ?: BtFormats.version(primary.contents.head as BTModel)
		for (copy : copies) {
			convert(copy)
		}
		for (target : targets.values.flatten) {
			if (!EcoreUtil.isAncestor(copies, copier.get(target))) {
				// e.g. value_B of a BlackboardCheck, which becomes part of a Precondition's script
				errors += new GenerationError(target, '''cannot weave into this element in a BehaviorTree.CPP «format» tree: the conversion to version «format» rewrites it''')
			}
		}
		if (!errors.empty) {
			return null
		}

		// Blackboard keys the runtime writes into the main tree (vp_sel, vp), by the tree reading them.
		val readers = new LinkedHashMap<BehaviorTree, Set<String>>
		for (vp : bound) {
			for (target : targets.get(vp)) {
				val copy = copier.get(target)
				val key = if (vp.isEnum) vp.selection else vp.name
				switch copy {
					Attribute: copy.value = "{" + key + "}"
					TreeNode: if (vp.isEnum) insert(vp, copy)
				}
				val reader = EcoreUtil2.getContainerOfType(copy, BehaviorTree)
				if (reader !== null && (vp.isEnum || copy instanceof Attribute)) {
					readers.computeIfAbsent(reader)[new LinkedHashSet] += key
				}
			}
		}
		exposeKeys(copies, readers)

		val out = factory.createBTModel
		out.attributes += copies.head.attributes.toList
		out.imports += includes(woven, bound).map[path|factory.createImport => [importURI = path]]
		copies.forEach[out.trees += trees.toList]
		out.nodesmodel = copies.head.nodesmodel
		nameMainTree(out)
		val monitored = bound.filter[isEnum].toList
		if (!monitored.empty) {
			monitor(out, monitored, m)
			if (out.nodesmodel !== null) {
				out.nodesmodel.content = declareVariantAction(out.nodesmodel.content)
			}
		}
		out
	}

	/**
	 * BehaviorTree.CPP 3 runs a file's only tree when no main_tree_to_execute is given, counting
	 * the included trees too. A woven file with several trees or includes therefore names its
	 * main tree; a main tree without ID (BehaviorTree.CPP's tutorial form) gets one first.
	 */
	def private nameMainTree(BTModel out) {
		if (out.main_tree_to_execute !== null || (out.trees.size <= 1 && out.imports.empty) || out.trees.empty) {
			return
		}
		val main = out.trees.head
		if (main.name === null || main.name.empty) {
			val taken = out.trees.map[name].toSet
			var id = "MainTree"
			for (var k = 2; taken.contains(id); k++) {
				id = "MainTree" + k
			}
			main.name = id
		}
		out.attributes += attribute("main_tree_to_execute", main.name)
	}

	// ------------------------------------------------------------------ BehaviorTree.CPP version

	/** A copied file of the other version, converted; what has no equivalent is reported at the original. */
	def private convert(BTModel copy) {
		if (BtFormats.version(copy) == format) {
			return
		}
		val originals = <EObject, EObject>newHashMap
		copier.forEach[original, copied|originals.put(copied, original)]
		val conversion = BtFormatConverter.convert(copy, format)
		// Targets are found through the copier: point it at the nodes that replaced converted ones.
		for (entry : copier.entrySet.toList) {
			val replacement = conversion.replacements.get(entry.value)
			if (replacement !== null) {
				entry.value = replacement
			}
		}
		for (problem : conversion.problems) {
			val original = originals.get(problem.element) ?: originals.get(copy)
			errors += new GenerationError(original, '''cannot weave a BehaviorTree.CPP «format» tree: «problem.message»''')
		}
		// _autoremap="false" only marks a converted SubTreePlus for the way back; a woven tree is not converted back.
		for (call : copy.eAllContents.filter(SubtreeNode).toList) {
			val marker = call.attributes.findFirst[name == "_autoremap" && value == "false"]
			if (marker !== null) {
				call.attributes -= marker
			}
		}
	}

	def private isV4() {
		format == 4
	}

	// ------------------------------------------------------------------ blackboard visibility

	/**
	 * A subtree called with its own blackboard (BehaviorTree.CPP's default) does not see the main
	 * tree's keys, where the runtime writes {vp_sel} and {vp}. Each key a subtree reads is remapped
	 * on every call between the main tree and that subtree: k="{k}" on a SubTreePlus and a version-4
	 * SubTree, k="k" on a version-3 SubTree; calls that share the blackboard or remap automatically
	 * pass it through as they are.
	 */
	def private exposeKeys(List<BTModel> copies, Map<BehaviorTree, Set<String>> readers) {
		val primary = copies.head
		val main = primary.main_tree_to_execute ?: primary.trees.head?.name
		val trees = copies.map[it.trees].flatten.toList
		val pending = new ArrayDeque<Pair<BehaviorTree, String>>
		readers.forEach[tree, keys|keys.forEach[key|pending += tree -> key]]
		val done = newHashSet
		while (!pending.empty) {
			val next = pending.poll
			val tree = next.key
			val key = next.value
			if (tree.name != main && done.add(tree.name + "/" + key)) {
				for (call : trees.map[eAllContents.filter(SubtreeNode).toList].flatten.filter[behaviorTree?.name == tree.name].toList) {
					if (!passesThrough(call) && call.attribute(key) === null) {
						call.attributes += attribute(key, if (call instanceof SubtreePlus || isV4) "{" + key + "}" else key)
					}
					pending += EcoreUtil2.getContainerOfType(call, BehaviorTree) -> key
				}
			}
		}
	}

	def private passesThrough(SubtreeNode call) {
		if (isV4) {
			return #["true", "True", "TRUE", "1"].contains(call.attribute("_autoremap"))
		}
		"true".equalsIgnoreCase(call.attribute("__shared_blackboard"))
			|| (call instanceof SubtreePlus && "true".equalsIgnoreCase(call.attribute("__autoremap")))
	}

	// ------------------------------------------------------------------ Switch insertion

	def private insert(SampledVarpoint vp, TreeNode target) {
		val binding = vp.varpoint.binding as BtBinding
		val cases = vp.literals.filter(BehaviorTreeLiteral).filter[!preset && reference !== null].toList
		if (cases.empty) {
			return // only the preset: the nominal behaviour needs no Switch
		}
		if (binding.insertionType == InsertionType.IN) {
			// The target moves inside the Switch as its default: park a placeholder there first.
			// A variant replacing a subtree call takes over its port wiring (goal="{ward}"...).
			val wiring = if (target instanceof SubtreeNode) target.attributes.filter[name != "name"].toList else #[]
			val placeholder = leaf(factory.createAlwaysSuccess, "AlwaysSuccess")
			val choice = switchFor(vp, cases, wiring, placeholder)
			EcoreUtil.replace(target, choice)
			EcoreUtil.replace(placeholder, target)
			return
		}
		val choice = switchFor(vp, cases, #[], leaf(factory.createAlwaysSuccess, "AlwaysSuccess"))
		val before = binding.insertionType == InsertionType.BEFORE
		val parent = target.eContainer
		if (parent instanceof ControlNode && !(parent instanceof Switch)) {
			val nodes = (parent as ControlNode).nodes
			val index = nodes.indexOf(target)
			nodes.add(if(before) index else index + 1, choice)
		} else {
			val sequence = factory.createSequence
			sequence.tag = "Sequence"
			EcoreUtil.replace(target, sequence)
			if (before) {
				sequence.nodes += choice
				sequence.nodes += target
			} else {
				sequence.nodes += target
				sequence.nodes += choice
			}
		}
	}

	/** A Switch over the cases whose last child is fallback; nested when there are more than six. */
	def private TreeNode switchFor(SampledVarpoint vp, List<BehaviorTreeLiteral> cases, List<Attribute> wiring,
		TreeNode fallback) {
		if (cases.size > MAX_CASES) {
			// Leave at least two cases to the inner Switch: there is no Switch1.
			val here = if(cases.size - MAX_CASES >= 2) MAX_CASES else cases.size - 2
			return switchNode(vp, cases.subList(0, here), wiring,
				switchFor(vp, cases.subList(here, cases.size), wiring, fallback))
		}
		switchNode(vp, cases, wiring, fallback)
	}

	def private switchNode(SampledVarpoint vp, List<BehaviorTreeLiteral> cases, List<Attribute> wiring,
		TreeNode fallback) {
		// A single case still needs a Switch2: its second case repeats the first, so it is never
		// chosen (the first matching case wins), and its child is an AlwaysFailure.
		val padded = cases.size == 1
		val node = factory.createSwitch
		node.tag = "Switch" + (if(padded) 2 else cases.size)
		node.attributes += attribute("variable", "{" + vp.selection + "}")
		for (i : 0 ..< cases.size) {
			node.attributes += attribute("case_" + (i + 1), cases.get(i).name)
		}
		if (padded) {
			node.attributes += attribute("case_2", cases.head.name)
		}
		for (c : cases) {
			val call = subtree(c.reference)
			call.attributes += wiring.map[a|attribute(a.name, a.value)]
			node.nodes += call
		}
		if (padded) {
			node.nodes += leaf(factory.createAlwaysFailure, "AlwaysFailure")
		}
		node.nodes += fallback
		node
	}

	// ------------------------------------------------------------------ monitoring

	def private monitor(BTModel out, List<SampledVarpoint> varpoints, AdaptationModel m) {
		val mainName = out.main_tree_to_execute ?: out.trees.head?.name
		val main = out.trees.findFirst[name == mainName]
		if (main === null || main.nodes.empty) {
			errors += new GenerationError(m.model.imports.head, '''cannot add the monitoring Parallel: the main tree '«mainName»' is not in the imported file itself''')
			return
		}
		val actions = varpoints.map[vp|
			val action = leaf(factory.createAction, "Action")
			action.attributes += attribute("ID", "VariantAction")
			action.attributes += attribute("varpoint", vp.name)
			action.attributes += attribute("value", "{" + vp.selection + "}")
			action as TreeNode
		]
		val repeat = factory.createRepeat
		repeat.tag = "Repeat"
		repeat.attributes += attribute("name", "monitoring_repeat")
		repeat.attributes += attribute("num_cycles", "-1")
		if (actions.size == 1) {
			repeat.node = actions.head
		} else {
			// VariantAction stays RUNNING (it monitors): a Sequence would only ever tick the first,
			// so several of them run side by side.
			val all = factory.createParallel
			all.tag = "Parallel"
			all.attributes += attribute("name", "monitoring_variants")
			all.attributes += attribute(if (isV4) "success_count" else "success_threshold", String.valueOf(actions.size))
			all.attributes += attribute(if (isV4) "failure_count" else "failure_threshold", "1")
			all.nodes += actions
			repeat.node = all
		}
		val parallel = factory.createParallel
		parallel.tag = "Parallel"
		parallel.attributes += attribute("name", "monitoring_parallel")
		parallel.attributes += attribute(if (isV4) "success_count" else "success_threshold", "1")
		parallel.attributes += attribute(if (isV4) "failure_count" else "failure_threshold", "1")
		val root = main.nodes.head
		EcoreUtil.replace(root, parallel)
		parallel.nodes += repeat
		parallel.nodes += root
	}

	/** Adds VariantAction to the TreeNodesModel, for editors such as Groot. */
	def static declareVariantAction(String content) {
		val end = content.lastIndexOf("</TreeNodesModel>")
		if (end < 0 || content.contains('"VariantAction"')) {
			return content
		}
		val lineStart = content.lastIndexOf("\n", end) + 1
		val indent = content.substring(lineStart, end)
		val declaration = '<Action ID="VariantAction"><input_port name="varpoint"/><output_port name="value"/></Action>'
		if (lineStart > 0 && indent.trim.empty) {
			content.substring(0, lineStart) + indent + "  " + declaration + "\n" + content.substring(lineStart)
		} else {
			content.substring(0, end) + declaration + content.substring(end)
		}
	}

	// ------------------------------------------------------------------ includes

	/**
	 * Includes of the woven tree, relative to where it is written: those of the copied files, then
	 * the files of variant trees not reachable through them; never a copied file, never twice.
	 */
	def private List<String> includes(Set<Resource> woven, List<SampledVarpoint> bound) {
		val uris = new LinkedHashSet<URI>
		val wovenUris = woven.map[URI].toSet
		for (r : woven) {
			uris += BtGlobalScopeProvider.includesOf(r).filter[!wovenUris.contains(it)]
		}
		val reachable = new LinkedHashSet<URI>(wovenUris)
		val resourceSet = woven.head.resourceSet
		for (uri : uris) {
			reachable += uri
			val r = resourceSet.getResource(uri, true)
			checkIncludedVersion(r)
			BtTrees.includedResources(r).forEach[reachable += URI]
		}
		for (vp : bound.filter[isEnum]) {
			for (literal : vp.literals.filter(BehaviorTreeLiteral).filter[reference !== null && !reference.eIsProxy]) {
				val r = literal.reference.eResource
				if (!reachable.contains(r.URI)) {
					checkIncludedVersion(r)
					uris += r.URI
					reachable += r.URI
					BtTrees.includedResources(r).forEach[reachable += URI]
				}
			}
		}
		uris.map[OutputLocation.relative(it, wovenTree)].toList
	}

	/** An included file is loaded as it is: it must already be in the woven tree's format. */
	def private checkIncludedVersion(Resource included) {
		val model = included.contents.head
		if (model instanceof BTModel) {
			val version = BtFormats.version(model)
			if (version != format) {
				errors += new GenerationError(model, '''the woven tree (BehaviorTree.CPP «format») includes «included.URI.lastSegment», a BehaviorTree.CPP «version» file: convert it with `miron convert --to «format»` or weave with --bt-format «version»''')
			}
		}
	}

	// ------------------------------------------------------------------ node factory

	def private attribute(String name, String value) {
		val a = factory.createAttribute
		a.name = name
		a.value = value
		a
	}

	def private <T extends TreeNode> T leaf(T node, String tag) {
		node.tag = tag
		node
	}

	/** A subtree call with its own blackboard: v3 SubTreePlus (which remaps with {key}), v4 SubTree. */
	def private SubtreeNode subtree(BehaviorTree tree) {
		val SubtreeNode node = if (isV4) factory.createSubtree else factory.createSubtreePlus
		node.tag = if (isV4) "SubTree" else "SubTreePlus"
		node.behaviorTree = copier.get(tree) as BehaviorTree ?: tree
		node
	}

}
