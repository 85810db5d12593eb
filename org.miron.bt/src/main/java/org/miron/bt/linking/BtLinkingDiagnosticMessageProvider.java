package org.miron.bt.linking;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.util.Suggestions;
import org.miron.bt.validation.BtIssueCodes;

import com.google.inject.Inject;

/**
 * Says what a user must fix when a reference (a SubTree ID) names nothing, with a stable code and,
 * as issue data, what a quick fix needs: the include to add when a file next to this one defines
 * the tree, else the visible names closest to the one written ("did you mean").
 */
public class BtLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

    @Inject
    private IScopeProvider scopeProvider;

    @Inject
    private IQualifiedNameConverter nameConverter;

    @Inject
    private MissingIncludes missingIncludes;

    @Override
    public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
        String[] closest = closest(context);
        if (context.getReference() == BtPackage.Literals.SUBTREE_NODE__BEHAVIOR_TREE) {
            String message = "unknown SubTree ID '" + context.getLinkText()
                    + "': no BehaviorTree with this ID in this file or the files it includes";
            String include = missingIncludes.find(context.getContext().eResource(), context.getLinkText());
            return include != null
                    ? new DiagnosticMessage(message, Severity.ERROR, BtIssueCodes.MISSING_INCLUDE, include)
                    : new DiagnosticMessage(message, Severity.ERROR, BtIssueCodes.UNKNOWN_SUBTREE, closest);
        }
        DiagnosticMessage message = super.getUnresolvedProxyMessage(context);
        return new DiagnosticMessage(message.getMessage(), message.getSeverity(), BtIssueCodes.UNKNOWN_REFERENCE,
                closest);
    }

    private String[] closest(ILinkingDiagnosticContext context) {
        List<String> names = new ArrayList<>();
        for (IEObjectDescription d : scopeProvider.getScope(context.getContext(), context.getReference())
                .getAllElements()) {
            names.add(nameConverter.toString(d.getName()));
        }
        return Suggestions.closest(context.getLinkText(), names).toArray(new String[0]);
    }
}
