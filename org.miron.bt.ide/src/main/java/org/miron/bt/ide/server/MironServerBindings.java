package org.miron.bt.ide.server;

import org.eclipse.xtext.ide.editor.syntaxcoloring.ISemanticHighlightingCalculator;
import org.eclipse.xtext.ide.server.codeActions.ICodeActionService2;
import org.eclipse.xtext.ide.server.formatting.FormattingService;
import org.eclipse.xtext.ide.server.occurrences.IDocumentHighlightService;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolKindProvider;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolService;
import org.eclipse.xtext.resource.EObjectAtOffsetHelper;
import org.eclipse.xtext.service.AbstractGenericModule;
import org.miron.bt.ide.codeactions.IssueDataCodeActions;

import com.google.inject.Binder;

/**
 * The language-server services all three languages share, in one place: quick fixes from the
 * issues' data, quiet formatting, navigation and rename on half-written text, symbol kinds,
 * semantic tokens and highlights of symbols only. Each language's ide module lays these over its
 * generated bindings (and adds its own hover, documentation and completion).
 */
public class MironServerBindings extends AbstractGenericModule {

    public Class<? extends ICodeActionService2> bindICodeActionService2() {
        return IssueDataCodeActions.class;
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
    public void configureSymbolKinds(Binder binder) {
        binder.bind(DocumentSymbolKindProvider.class).to(MironSymbolKinds.class);
    }

    public Class<? extends ISemanticHighlightingCalculator> bindISemanticHighlightingCalculator() {
        return MironSemanticHighlighter.class;
    }

    public Class<? extends IDocumentHighlightService> bindIDocumentHighlightService() {
        return SymbolOnlyHighlightService.class;
    }
}
