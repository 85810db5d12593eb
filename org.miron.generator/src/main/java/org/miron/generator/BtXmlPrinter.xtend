package org.miron.generator

import org.miron.bt.bt.BTModel
import org.miron.bt.bt.Attribute
import org.miron.bt.bt.ControlNode
import org.miron.bt.bt.DecoratorNode
import org.miron.bt.bt.SubtreeNode
import org.miron.bt.bt.TreeNode
import java.util.List

import static org.miron.bt.conversion.XmlStrings.quote

/**
 * Prints a BT model as BehaviorTree.CPP 3 XML: two-space indentation, attributes in model order
 * (a subtree's ID first), the TreeNodesModel verbatim. Comments of the source are not in the
 * model and so are not printed.
 */
class BtXmlPrinter {

	def String print(BTModel m, String comment) {
		// Plain concatenation: a rich string would re-indent the verbatim TreeNodesModel.
		val out = new StringBuilder
		out.append('<?xml version="1.0"?>\n')
		out.append("<!-- " + comment.replace("--", "- -") + " -->\n") // "--" may not occur in a comment
		out.append("<root" + attributes(m.attributes) + ">\n")
		for (include : m.imports) {
			out.append("  <include path=" + quote(include.importURI) + "/>\n")
		}
		for (tree : m.trees) {
			out.append("\n  <BehaviorTree ID=" + quote(tree.name) + attributes(tree.attributes) + ">\n")
			for (node : tree.nodes) {
				out.append(node(node, "    ")).append("\n")
			}
			out.append("  </BehaviorTree>\n")
		}
		if (m.nodesmodel !== null) {
			out.append("\n  " + m.nodesmodel.content + "\n")
		}
		out.append("\n</root>\n")
		out.toString
	}

	/** One node and its subtree, every line starting with indent (no trailing newline). */
	def String node(TreeNode n, String indent) {
		val head = indent + "<" + n.tag + id(n) + attributes(n.attributes)
		val children = children(n)
		if (children.empty) {
			return head + "/>"
		}
		head + ">\n" + children.map[node(it, indent + "  ")].join("\n") + "\n" + indent + "</" + n.tag + ">"
	}

	def private id(TreeNode n) {
		if (n instanceof SubtreeNode) " ID=" + quote(n.behaviorTree?.name ?: "") else ""
	}

	def private attributes(List<Attribute> attributes) {
		attributes.map[" " + name + "=" + quote(value ?: "")].join
	}

	def private List<TreeNode> children(TreeNode n) {
		switch n {
			ControlNode: n.nodes
			DecoratorNode: (if (n.node === null) #[] else #[n.node]) + n.surplus
			default: #[]
		}.toList
	}
}
