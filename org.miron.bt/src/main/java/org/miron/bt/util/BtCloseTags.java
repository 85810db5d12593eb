package org.miron.bt.util;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.TerminalRule;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.bt.ForeignElement;
import org.miron.bt.bt.TreeNode;

/**
 * The closing name of a compact element ({@code <GoTo></GoTo>}, {@code <RateController>...</RateController>})
 * as written. The grammar does not assign it to the model, so it is read from the node model: it is
 * the element's own last NAME token that no assignment consumed.
 */
public final class BtCloseTags {
    private BtCloseTags() {
    }

    /** The leaf holding the closing name, or null when the element has none (written as {@code <x/>}). */
    public static ILeafNode closingName(TreeNode element) {
        ICompositeNode node = NodeModelUtils.getNode(element);
        if (node == null) {
            return null;
        }
        List<ILeafNode> tokens = new ArrayList<>();
        for (ILeafNode leaf : node.getLeafNodes()) {
            if (!leaf.isHidden()) {
                tokens.add(leaf);
            }
        }
        // The element ends with '</' NAME '>': look at the token before the last one only.
        if (tokens.size() < 2) {
            return null;
        }
        ILeafNode candidate = tokens.get(tokens.size() - 2);
        return isUnassignedName(candidate) ? candidate : null;
    }

    /** The leaf holding the closing name of an element BehaviorTree.CPP ignores, or null for {@code <x/>}. */
    public static ILeafNode closingName(ForeignElement element) {
        ICompositeNode node = NodeModelUtils.getNode(element);
        if (node == null) {
            return null;
        }
        // '</' ForeignName '>': the last unassigned ForeignName call among the element's own children.
        ILeafNode closing = null;
        for (INode child : node.getChildren()) {
            if (child.getGrammarElement() instanceof RuleCall call && "ForeignName".equals(call.getRule().getName())
                    && GrammarUtil.containingAssignment(call) == null) {
                for (ILeafNode leaf : child.getLeafNodes()) {
                    if (!leaf.isHidden()) {
                        closing = leaf;
                    }
                }
            }
        }
        return closing;
    }

    private static boolean isUnassignedName(ILeafNode leaf) {
        if (!(leaf.getGrammarElement() instanceof RuleCall call) || !(call.getRule() instanceof TerminalRule rule)) {
            return false;
        }
        Assignment assignment = GrammarUtil.containingAssignment(call);
        return "NAME".equals(rule.getName()) && assignment == null;
    }
}
