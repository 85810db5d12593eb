package org.miron.dsl.ide.hover;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.hover.HoverContext;
import org.eclipse.xtext.ide.server.hover.HoverService;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.roqme.FunctionCall;

/**
 * Xtext's hover, also over a function's name ({@code count(...)}, {@code x'avg}) and a temporal
 * operator ({@code always}, {@code eventually within ...}): Xtext hovers only names of elements and
 * references, and neither has a name.
 */
public class DslHoverService extends HoverService {

    @Override
    protected HoverContext createContext(Document document, XtextResource resource, int offset) {
        HoverContext context = super.createContext(document, resource, offset);
        if (context != null && context.getRegion() != null && context.getRegion().contains(offset)
                || resource.getParseResult() == null) {
            return context;
        }
        ILeafNode leaf = NodeModelUtils.findLeafNodeAtOffset(resource.getParseResult().getRootNode(), offset);
        EObject element = leaf == null ? null : NodeModelUtils.findActualSemanticObjectFor(leaf);
        if (element instanceof FunctionCall call && leaf.getText().equals(call.getFunction())
                || element instanceof TemporalExpression temporal && temporal.getOperator() != null
                        && leaf.getText().equals(temporal.getOperator().getLiteral())) {
            return new HoverContext(document, resource, offset, leaf.getTextRegion(), element);
        }
        return context;
    }
}
