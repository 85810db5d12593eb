package org.miron.bt.serializer;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.nodemodel.INode;
import org.miron.bt.bt.TreeNode;

/**
 * Writes the closing name of a compact element ({@code </RateController>}). The grammar leaves it
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
}
