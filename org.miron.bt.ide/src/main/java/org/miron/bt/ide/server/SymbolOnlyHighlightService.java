package org.miron.bt.ide.server;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.server.occurrences.DefaultDocumentHighlightService;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;

/**
 * Document highlights only for a symbol under the cursor: a reference or the name of a
 * declaration. Xtext's default also answered on keywords and punctuation, with the whole
 * enclosing element: opening a file (cursor on {@code import}) greyed every declaration in VS Code.
 */
public class SymbolOnlyHighlightService extends DefaultDocumentHighlightService {

    @Override
    protected boolean isDocumentHighlightAvailableFor(EObject selected, XtextResource resource, int offset) {
        if (!super.isDocumentHighlightAvailableFor(selected, resource, offset)) {
            return false;
        }
        ICompositeNode root = resource.getParseResult().getRootNode();
        // The cursor may stand just after the word (the end of a selection).
        return isSymbol(NodeModelUtils.findLeafNodeAtOffset(root, offset))
                || offset > 0 && isSymbol(NodeModelUtils.findLeafNodeAtOffset(root, offset - 1));
    }

    private static boolean isSymbol(ILeafNode leaf) {
        if (leaf == null || leaf.isHidden() || leaf.getGrammarElement() instanceof Keyword) {
            return false;
        }
        // Up from the token to the first assignment: a token of a data-type rule (a qualified name's
        // segment) is assigned, or is a cross-reference, where the rule is called.
        for (INode node = leaf; node != null; node = node.getParent()) {
            EObject element = node.getGrammarElement();
            if (element == null) {
                continue;
            }
            if (GrammarUtil.containingCrossReference(element) != null) {
                return true;
            }
            Assignment assignment = GrammarUtil.containingAssignment(element);
            if (assignment != null) {
                return "name".equals(assignment.getFeature());
            }
        }
        return false;
    }
}
