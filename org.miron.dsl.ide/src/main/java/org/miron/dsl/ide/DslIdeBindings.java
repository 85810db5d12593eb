package org.miron.dsl.ide;

import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeCrossrefProposalProvider;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.miron.bt.ide.server.MironServerBindings;
import org.miron.dsl.ide.contentassist.DslCrossrefProposalProvider;
import org.miron.dsl.ide.contentassist.DslProposalProvider;
import org.miron.dsl.ide.hover.DslDocumentationProvider;
import org.miron.dsl.ide.hover.DslHoverService;

/**
 * The ide services RoQME and MIRoN share (their generated ide modules are unrelated classes): the
 * server bindings of all three languages, and the two languages' own hover, documentation and
 * completion.
 */
public class DslIdeBindings extends MironServerBindings {

    public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
        return DslDocumentationProvider.class;
    }

    public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
        return DslProposalProvider.class;
    }

    public Class<? extends IdeCrossrefProposalProvider> bindIdeCrossrefProposalProvider() {
        return DslCrossrefProposalProvider.class;
    }

    public Class<? extends IHoverService> bindIHoverService() {
        return DslHoverService.class;
    }
}
