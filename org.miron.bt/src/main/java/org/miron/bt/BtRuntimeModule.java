package org.miron.bt;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.parser.antlr.Lexer;
import org.eclipse.xtext.parser.antlr.LexerBindings;
import org.eclipse.xtext.parser.antlr.LexerProvider;
import org.eclipse.xtext.resource.IDefaultResourceDescriptionStrategy;
import org.eclipse.xtext.scoping.IGlobalScopeProvider;
import org.eclipse.xtext.serializer.sequencer.ISyntacticSequencer;
import org.miron.bt.conversion.BtValueConverterService;
import org.miron.bt.formatting2.BtFormatter;
import org.miron.bt.linking.BtLinkingDiagnosticMessageProvider;
import org.miron.bt.naming.BtQualifiedNameProvider;
import org.miron.bt.parser.BtLexer;
import org.miron.bt.parser.BtSyntaxErrorMessageProvider;
import org.miron.bt.parser.antlr.lexer.InternalBtLexer;
import org.miron.bt.resource.BtResourceDescriptionStrategy;
import org.miron.bt.scoping.BtGlobalScopeProvider;
import org.miron.bt.serializer.BtCloseTagSequencer;

import com.google.inject.Binder;
import com.google.inject.Provider;
import com.google.inject.name.Names;

/** Guice bindings of the BT language's runtime services. */
public class BtRuntimeModule extends AbstractBtRuntimeModule {

    // The hand-written lexer (opaque TreeNodesModel) replaces the generated one everywhere.
    @Override
    public Class<? extends Lexer> bindLexer() {
        return BtLexer.class;
    }

    @Override
    public Provider<? extends InternalBtLexer> provideInternalBtLexer() {
        return LexerProvider.create(BtLexer.class);
    }

    @Override
    public void configureRuntimeLexer(Binder binder) {
        binder.bind(Lexer.class).annotatedWith(Names.named(LexerBindings.RUNTIME)).to(BtLexer.class);
    }

    @Override
    public Class<? extends IValueConverterService> bindIValueConverterService() {
        return BtValueConverterService.class;
    }

    @Override
    public Class<? extends IQualifiedNameProvider> bindIQualifiedNameProvider() {
        return BtQualifiedNameProvider.class;
    }

    @Override
    public Class<? extends IGlobalScopeProvider> bindIGlobalScopeProvider() {
        return BtGlobalScopeProvider.class;
    }

    public Class<? extends IFormatter2> bindIFormatter2() {
        return BtFormatter.class;
    }

    // Compact elements' closing names are not in the model: written back from the tag.
    @Override
    public Class<? extends ISyntacticSequencer> bindISyntacticSequencer() {
        return BtCloseTagSequencer.class;
    }

    // A tree repeated with the same ID and content is not exported twice (issue 17).
    public Class<? extends IDefaultResourceDescriptionStrategy> bindIDefaultResourceDescriptionStrategy() {
        return BtResourceDescriptionStrategy.class;
    }

    public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
        return BtLinkingDiagnosticMessageProvider.class;
    }

    // No follow-on errors of a syntax error (issue 23, item 8).
    public Class<? extends org.eclipse.xtext.validation.IResourceValidator> bindIResourceValidator() {
        return org.miron.bt.validation.BtResourceValidator.class;
    }

    // Syntax errors carry the BT language's issue code (BtIssueCodes.SYNTAX_ERROR).
    public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
        return BtSyntaxErrorMessageProvider.class;
    }
}
