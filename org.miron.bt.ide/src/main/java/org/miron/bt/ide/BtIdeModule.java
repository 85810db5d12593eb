package org.miron.bt.ide;

import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.ide.LexerIdeBindings;
import org.eclipse.xtext.ide.editor.contentassist.CompletionPrefixProvider;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.antlr.internal.Lexer;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.miron.bt.ide.contentassist.BtProposalProvider;
import org.miron.bt.ide.contentassist.antlr.BtContentAssistLexer;
import org.miron.bt.ide.hover.BtDocumentationProvider;
import org.miron.bt.ide.hover.BtHoverService;
import org.miron.bt.ide.server.MironServerBindings;

import com.google.inject.Binder;
import com.google.inject.name.Names;
import com.google.inject.util.Modules;

/** Guice bindings of the BT language's ide services (used by the language server). */
public class BtIdeModule extends AbstractBtIdeModule {

    @Override
    public void configure(Binder binder) {
        Modules.override(super::configure).with(new MironServerBindings()).configure(binder);
    }

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

    public Class<? extends IHoverService> bindIHoverService() {
        return BtHoverService.class;
    }

    public Class<? extends IdeContentProposalProvider> bindIdeContentProposalProvider() {
        return BtProposalProvider.class;
    }
}
