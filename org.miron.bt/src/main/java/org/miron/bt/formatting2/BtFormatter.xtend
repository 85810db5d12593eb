package org.miron.bt.formatting2

import org.eclipse.emf.ecore.EObject
import org.eclipse.xtext.formatting2.AbstractFormatter2
import org.eclipse.xtext.formatting2.IFormattableDocument
import org.eclipse.xtext.formatting2.ITextReplacer
import org.eclipse.xtext.formatting2.ITextReplacerContext
import org.eclipse.xtext.formatting2.internal.CommentReplacer
import org.eclipse.xtext.formatting2.internal.WhitespaceReplacer
import org.eclipse.xtext.formatting2.regionaccess.IComment
import org.miron.bt.bt.Attribute
import org.miron.bt.bt.BTModel
import org.miron.bt.bt.BehaviorTree
import org.miron.bt.bt.ForeignElement
import org.miron.bt.bt.Import
import org.miron.bt.bt.TreeNode
import org.miron.bt.bt.TreeNodesModel

/**
 * Tidy XML: one element per line, children indented one level, attributes one space apart with
 * no space around '=', at most one blank line kept between elements. Comments and the opaque
 * TreeNodesModel are kept as written.
 * A model with no text of its own (serialized from memory, as the woven tree; see BtFormatting)
 * gets a blank line before each tree, the TreeNodesModel and </root>: the formatter uses a default
 * line count only where the text has no whitespace yet, so parsed files keep their own.
 */
class BtFormatter extends AbstractFormatter2 {

	def dispatch void format(BTModel model, extension IFormattableDocument document) {
		model.formatElement(document)
		model.eContents.forEach[format]
	}

	def dispatch void format(Import include, extension IFormattableDocument document) {
		include.formatElement(document)
	}

	def dispatch void format(BehaviorTree tree, extension IFormattableDocument document) {
		tree.formatElement(document)
		tree.eContents.forEach[format]
	}

	def dispatch void format(TreeNode node, extension IFormattableDocument document) {
		node.formatElement(document)
		node.eContents.forEach[format]
	}

	def dispatch void format(ForeignElement element, extension IFormattableDocument document) {
		element.formatElement(document)
		element.eContents.forEach[format]
	}

	def dispatch void format(TreeNodesModel nodesModel, extension IFormattableDocument document) {
		nodesModel.prepend[setNewLines(1, 2, 2)]
	}

	def dispatch void format(Attribute attribute, extension IFormattableDocument document) {
		attribute.prepend[oneSpace]
		attribute.regionFor.keyword("=").surround[noSpace]
	}

	/** XML comments and processing instructions are kept verbatim, on a line of their own if written so. */
	override ITextReplacer createCommentReplacer(IComment comment) {
		new CommentReplacer(comment) {
			override configureWhitespace(WhitespaceReplacer leading, WhitespaceReplacer trailing) {
				keepLineBreak(leading)
				keepLineBreak(trailing)
			}

			override createReplacements(ITextReplacerContext context) {
				context
			}
		}
	}

	def private static void keepLineBreak(WhitespaceReplacer whitespace) {
		val region = whitespace.region
		if (region.offset == 0) {
			whitespace.formatting.space = ""
		} else if (region.text.contains("\n")) {
			whitespace.formatting.newLinesMin = 1
			whitespace.formatting.newLinesDefault = 1
			whitespace.formatting.newLinesMax = 2
		} else if (region.endOffset < region.textRegionAccess.regionForDocument.endOffset) {
			whitespace.formatting.space = " "
		}
	}

	def private void formatElement(EObject element, extension IFormattableDocument document) {
		val regions = element.regionFor
		if (element.eContainer !== null) {
			val blankLine = if (element instanceof BehaviorTree) 2 else 1
			regions.keyword("<").prepend[setNewLines(1, blankLine, 2)]
		}
		regions.keyword("<").append[noSpace]
		// Attributes the grammar spells out (ID of trees and subtrees, path of includes).
		for (name : regions.keywords("ID", "path")) {
			name.prepend[oneSpace]
		}
		for (equals : regions.keywords("=")) {
			equals.surround[noSpace]
		}
		regions.keyword("/>").prepend[noSpace]
		val ends = regions.keywords(">")
		val close = regions.keyword("</")
		if (!ends.empty) {
			ends.head.prepend[noSpace]
		}
		if (close !== null) {
			interior(ends.head, close)[indent]
			val blankLine = element instanceof BTModel && close.previousHiddenRegion.undefined
			close.prepend[setNewLines(if (blankLine) 2 else 1)]
			close.append[noSpace]
			ends.get(ends.size - 1).prepend[noSpace]
		}
	}
}
