package org.miron.bt.linking;

import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.miron.bt.bt.BtPackage;

/** Says what a user must fix when a SubTree ID names no tree. */
public class BtLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

    public static final String UNKNOWN_SUBTREE = "org.miron.bt.unknownSubtree";

    @Override
    public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
        if (context.getReference() == BtPackage.Literals.SUBTREE_NODE__BEHAVIOR_TREE) {
            return new DiagnosticMessage("unknown SubTree ID '" + context.getLinkText()
                    + "': no BehaviorTree with this ID in this file or the files it includes",
                    Severity.ERROR, UNKNOWN_SUBTREE);
        }
        return super.getUnresolvedProxyMessage(context);
    }
}
