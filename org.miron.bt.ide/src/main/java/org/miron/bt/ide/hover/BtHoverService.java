package org.miron.bt.ide.hover;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.ide.server.hover.HoverContext;
import org.eclipse.xtext.ide.server.hover.HoverService;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.TreeNode;

/**
 * Xtext's hover, also over an attribute's value and over an element's name: the significant
 * region of an attribute is its name, so {@code <Action ID="MoveTo"/>} had no hover on "MoveTo",
 * where the reader points, and a built-in such as {@code <Repeat>} had none at all.
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
        // Over an element's name: the node (the significant region Xtext looks for is a name feature it has not).
        if (element instanceof Attribute || element instanceof TreeNode node && leaf.getText().equals(node.getTag())) {
            return new HoverContext(document, resource, offset, leaf.getTextRegion(), element);
        }
        return context;
    }
}
