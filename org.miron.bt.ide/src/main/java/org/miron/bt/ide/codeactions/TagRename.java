package org.miron.bt.ide.codeactions;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.bt.TreeNode;

/** Renames a BT element in its start and its end tag: the tokens of the element itself, not of its children. */
final class TagRename {

    private TagRename() {
    }

    static List<TextEdit> edits(Resource resource, Document document, Range tagRange, String newTag) {
        if (!(resource instanceof XtextResource xtext) || xtext.getParseResult() == null) {
            return List.of();
        }
        int offset = document.getOffSet(tagRange.getStart());
        ILeafNode tagLeaf = NodeModelUtils.findLeafNodeAtOffset(xtext.getParseResult().getRootNode(), offset);
        EObject element = tagLeaf == null ? null : NodeModelUtils.findActualSemanticObjectFor(tagLeaf);
        if (!(element instanceof TreeNode node)) {
            return List.of();
        }
        ICompositeNode elementNode = NodeModelUtils.findActualNodeFor(node);
        List<TextEdit> edits = new ArrayList<>();
        for (ILeafNode leaf : elementNode.getLeafNodes()) {
            if (!leaf.isHidden() && leaf.getText().equals(node.getTag())
                    && NodeModelUtils.findActualSemanticObjectFor(leaf) == node) {
                edits.add(new TextEdit(new Range(document.getPosition(leaf.getOffset()),
                        document.getPosition(leaf.getEndOffset())), newTag));
            }
        }
        return edits;
    }
}
