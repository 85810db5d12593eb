package org.miron.bt.formats;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.LineAndColumn;

/** An element of the file that the other version cannot express, with its position (1-based; 0 when unknown). */
public final class ConversionProblem {
    private final EObject element;
    private final String message;
    private final String code;
    private final int line;
    private final int column;

    ConversionProblem(EObject element, String message, String code) {
        this.element = element;
        this.message = message;
        this.code = code;
        ICompositeNode node = NodeModelUtils.getNode(element);
        if (node == null) {
            line = 0;
            column = 0;
        } else {
            // The element's first non-hidden character: '<' of the tag, the name of an attribute.
            LineAndColumn position = NodeModelUtils.getLineAndColumn(node, node.getOffset());
            line = position.getLine();
            column = position.getColumn();
        }
    }

    /** The node or attribute without equivalent. */
    public EObject getElement() {
        return element;
    }

    public String getMessage() {
        return message;
    }

    /** The issue code (BtIssueCodes.NO_V3_EQUIVALENT or NO_V4_EQUIVALENT). */
    public String getCode() {
        return code;
    }

    public int getLine() {
        return line;
    }

    public int getColumn() {
        return column;
    }

    /** {@code file:line:col: error [code]: message}. */
    public String format(String file) {
        return file + ":" + line + ":" + column + ": error [" + code + "]: " + message;
    }
}
