package org.miron.bt.ide.hover;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.hover.HoverContext;
import org.eclipse.xtext.ide.server.hover.HoverService;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.bt.Attribute;

/**
 * Xtext's hover, also over an attribute's value: the significant region of an attribute is its
 * name, so {@code <Action ID="MoveTo"/>} had no hover on "MoveTo", where the reader points.
 */
public class BtHoverService extends HoverService {

    @Override
    protected HoverContext createContext(Document document, XtextResource resource, int offset) {
        HoverContext context = super.createContext(document, resource, offset);
        if (context != null && context.getRegion() != null && context.getRegion().contains(offset)) {
            return context;
        }
        if (resource.getParseResult() == null) {
            return context;
        }
        ILeafNode leaf = NodeModelUtils.findLeafNodeAtOffset(resource.getParseResult().getRootNode(), offset);
        EObject element = leaf == null ? null : NodeModelUtils.findActualSemanticObjectFor(leaf);
        if (element instanceof Attribute) {
            return new HoverContext(document, resource, offset, leaf.getTextRegion(), element);
        }
        return context;
    }
}
