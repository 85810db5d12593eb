package org.miron.dsl.ide;

import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeCrossrefProposalProvider;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.eclipse.xtext.ide.server.formatting.FormattingService;
import org.eclipse.xtext.resource.EObjectAtOffsetHelper;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolService;
import org.eclipse.xtext.ide.server.occurrences.IDocumentHighlightService;
import org.eclipse.xtext.service.AbstractGenericModule;
import org.miron.bt.ide.codeactions.IssueDataCodeActions;
import org.miron.bt.ide.server.NamelessSafeOffsetHelper;
import org.miron.bt.ide.server.PlainErrorRenameService;
import org.miron.bt.ide.server.ResolvedOnlySymbolService;
import org.miron.bt.ide.server.SymbolOnlyHighlightService;
import org.miron.bt.ide.server.SyntaxSafeFormattingService;
import org.miron.dsl.ide.contentassist.DslCrossrefProposalProvider;
import org.miron.dsl.ide.contentassist.DslProposalProvider;
import org.miron.dsl.ide.hover.DslDocumentationProvider;

/** The ide services RoQME and MIRoN share (their generated ide modules are unrelated classes). */
public class DslIdeBindings extends AbstractGenericModule {

    public Class<? extends ICodeActionService2> bindICodeActionService2() {
        return IssueDataCodeActions.class;
    }

    public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
        return DslDocumentationProvider.class;
    }

    public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
        return DslProposalProvider.class;
    }

    public Class<? extends IdeCrossrefProposalProvider> bindIdeCrossrefProposalProvider() {
        return DslCrossrefProposalProvider.class;
    }

    public Class<? extends FormattingService> bindFormattingService() {
        return SyntaxSafeFormattingService.class;
    }

    public Class<? extends DocumentSymbolService> bindDocumentSymbolService() {
        return ResolvedOnlySymbolService.class;
    }

    public Class<? extends IRenameService2> bindIRenameService2() {
        return PlainErrorRenameService.class;
    }

    public Class<? extends EObjectAtOffsetHelper> bindEObjectAtOffsetHelper() {
        return NamelessSafeOffsetHelper.class;
    }

    // A nested class: Xtext's bind-method naming cannot name it.
    public void configureSymbolKinds(com.google.inject.Binder binder) {
        binder.bind(org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolKindProvider.class)
                .to(org.miron.bt.ide.server.MironSymbolKinds.class);
    }

    public Class<? extends org.eclipse.xtext.ide.editor.syntaxcoloring.ISemanticHighlightingCalculator> bindISemanticHighlightingCalculator() {
        return org.miron.bt.ide.server.MironSemanticHighlighter.class;
    }

    public Class<? extends org.eclipse.xtext.ide.server.hover.IHoverService> bindIHoverService() {
        return org.miron.dsl.ide.hover.DslHoverService.class;
    }

    public Class<? extends IDocumentHighlightService> bindIDocumentHighlightService() {
        return SymbolOnlyHighlightService.class;
    }
}
