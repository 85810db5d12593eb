package org.miron.diagram;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;

/**
 * Where a diagram node is written: the file's URI and the element's text range, lines and
 * characters counted from 0 as LSP counts them (an editor reveals it when the node is clicked).
 */
public record SourceSpan(String uri, int startLine, int startCharacter, int endLine, int endCharacter) {

    /** The span of a parsed model element, or null (no text behind it). */
    public static SourceSpan of(EObject element) {
        ICompositeNode node = element == null ? null : NodeModelUtils.findActualNodeFor(element);
        if (node == null || element.eResource() == null) {
            return null;
        }
        var start = NodeModelUtils.getLineAndColumn(node, node.getOffset());
        var end = NodeModelUtils.getLineAndColumn(node, node.getEndOffset());
        return new SourceSpan(element.eResource().getURI().toString(), start.getLine() - 1, start.getColumn() - 1,
                end.getLine() - 1, end.getColumn() - 1);
    }

    /** {@code file:line:col}, 1-based, as messages name places (the SVG's tooltips). */
    public String where() {
        String file = uri.substring(uri.lastIndexOf('/') + 1);
        return file + ":" + (startLine + 1) + ":" + (startCharacter + 1);
    }
}
