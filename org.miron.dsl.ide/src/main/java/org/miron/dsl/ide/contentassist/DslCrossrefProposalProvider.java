package org.miron.dsl.ide.contentassist;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IdeCrossrefProposalProvider;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.miron.dsl.ide.hover.DslDocumentationProvider;

/**
 * Cross-reference proposals written as the reference's syntax wants: enum literals as
 * {@code task::dock} (EnumLiteralName), everything else with dots ({@code roqme.safety}); each
 * with the documentation comment of what it names.
 */
public class DslCrossrefProposalProvider extends IdeCrossrefProposalProvider {

    @Override
    protected ContentAssistEntry createProposal(IEObjectDescription candidate, CrossReference crossRef,
            ContentAssistContext context) {
        ContentAssistEntry entry;
        if (crossRef.getTerminal() instanceof RuleCall call && "EnumLiteralName".equals(call.getRule().getName())) {
            entry = getProposalCreator().createProposal(String.join("::", candidate.getName().getSegments()), context,
                    e -> {
                        e.setSource(candidate);
                        e.setDescription("enum literal");
                        e.setKind(ContentAssistEntry.KIND_VALUE);
                    });
        } else {
            entry = super.createProposal(candidate, crossRef, context);
        }
        if (entry != null && context.getResource() != null) {
            // The element's documentation comment, from this file or an imported one (already loaded).
            EObject element = EcoreUtil.resolve(candidate.getEObjectOrProxy(), context.getResource());
            if (!element.eIsProxy()) {
                entry.setDocumentation(DslDocumentationProvider.plainDocumentation(element));
            }
        }
        return entry;
    }
}
