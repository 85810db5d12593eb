package org.miron.bt.serializer;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.nodemodel.INode;
import org.miron.bt.bt.ForeignElement;
import org.miron.bt.bt.TreeNode;

/**
 * Writes the closing name of a compact element ({@code </RateController>}) or of an element
 * BehaviorTree.CPP ignores ({@code </TreeNodeModel>}). The grammar leaves it
 * unassigned (it cannot require two NAMEs to be equal), so it is taken from the element's tag,
 * which is what the opening name was parsed into; the validator reports a mismatch when parsing.
 */
public class BtCloseTagSequencer extends BtSyntacticSequencer {

    @Override
    protected String getNAMEToken(EObject semanticObject, RuleCall ruleCall, INode node) {
        if (semanticObject instanceof TreeNode element && element.getTag() != null) {
            return element.getTag();
        }
        return super.getNAMEToken(semanticObject, ruleCall, node);
    }

    @Override
    protected String getForeignNameToken(EObject semanticObject, RuleCall ruleCall, INode node) {
        if (semanticObject instanceof ForeignElement element && element.getTag() != null) {
            return element.getTag();
        }
        return super.getForeignNameToken(semanticObject, ruleCall, node);
    }
}
