package org.miron.bt.ide;

import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.ide.LexerIdeBindings;
import org.eclipse.xtext.ide.editor.contentassist.CompletionPrefixProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.antlr.internal.Lexer;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.eclipse.xtext.ide.server.formatting.FormattingService;
import org.eclipse.xtext.resource.EObjectAtOffsetHelper;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolService;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.eclipse.xtext.ide.server.occurrences.IDocumentHighlightService;
import org.miron.bt.ide.codeactions.IssueDataCodeActions;
import org.miron.bt.ide.contentassist.BtProposalProvider;
import org.miron.bt.ide.contentassist.antlr.BtContentAssistLexer;
import org.miron.bt.ide.server.NamelessSafeOffsetHelper;
import org.miron.bt.ide.server.PlainErrorRenameService;
import org.miron.bt.ide.server.ResolvedOnlySymbolService;
import org.miron.bt.ide.server.SymbolOnlyHighlightService;
import org.miron.bt.ide.server.SyntaxSafeFormattingService;
import org.miron.bt.ide.hover.BtDocumentationProvider;
import org.miron.bt.ide.hover.BtHoverService;

import com.google.inject.Binder;
import com.google.inject.name.Names;

/** Guice bindings of the BT language's ide services (used by the language server). */
public class BtIdeModule extends AbstractBtIdeModule {

    // The content-assist lexer must cut <TreeNodesModel> into one token, as the runtime lexer does.
    @Override
    public void configureContentAssistLexer(Binder binder) {
        binder.bind(Lexer.class).annotatedWith(Names.named(LexerIdeBindings.CONTENT_ASSIST))
                .to(BtContentAssistLexer.class);
    }

    // The grammar's synthetic token is not indentation: the plain prefix provider fits.
    @Override
    public Class<? extends CompletionPrefixProvider> bindCompletionPrefixProvider() {
        return CompletionPrefixProvider.class;
    }

    public Class<? extends IEObjectDocumentationProvider> bindIEObjectDocumentationProvider() {
        return BtDocumentationProvider.class;
    }

    public Class<? extends ICodeActionService2> bindICodeActionService2() {
        return IssueDataCodeActions.class;
    }

    public Class<? extends IHoverService> bindIHoverService() {
        return BtHoverService.class;
    }

    public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
        return BtProposalProvider.class;
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

    public Class<? extends IDocumentHighlightService> bindIDocumentHighlightService() {
        return SymbolOnlyHighlightService.class;
    }
}
