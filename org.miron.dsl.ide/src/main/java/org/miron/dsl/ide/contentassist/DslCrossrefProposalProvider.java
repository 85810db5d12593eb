package org.miron.dsl.ide.contentassist;

import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IdeCrossrefProposalProvider;
import org.eclipse.xtext.resource.IEObjectDescription;

/**
 * Cross-reference proposals written as the reference's syntax wants: enum literals as
 * {@code task::dock} (EnumLiteralName), everything else with dots ({@code roqme.safety}).
 */
public class DslCrossrefProposalProvider extends IdeCrossrefProposalProvider {

    @Override
    protected ContentAssistEntry createProposal(IEObjectDescription candidate, CrossReference crossRef,
            ContentAssistContext context) {
        if (crossRef.getTerminal() instanceof RuleCall call && "EnumLiteralName".equals(call.getRule().getName())) {
            return getProposalCreator().createProposal(String.join("::", candidate.getName().getSegments()), context,
                    entry -> {
                        entry.setSource(candidate);
                        entry.setDescription("enum literal");
                        entry.setKind(ContentAssistEntry.KIND_VALUE);
                    });
        }
        return super.createProposal(candidate, crossRef, context);
    }
}
