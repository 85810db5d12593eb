package org.miron.dsl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.miron.dsl.conversion.DslValueConverterService;
import org.miron.dsl.parser.DslSyntaxErrorMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.miron.dsl.linking.DslLinkingDiagnosticMessageProvider;
import org.miron.dsl.naming.DslQualifiedNameConverter;
import org.miron.dsl.naming.DslQualifiedNameProvider;

/** Guice bindings of the RoQME language's runtime services (MIRoN repeats them). */
public class RoqmeRuntimeModule extends AbstractRoqmeRuntimeModule {

    @Override
    public Class<? extends IQualifiedNameProvider> bindIQualifiedNameProvider() {
        return DslQualifiedNameProvider.class;
    }

    public Class<? extends IQualifiedNameConverter> bindIQualifiedNameConverter() {
        return DslQualifiedNameConverter.class;
    }

    public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
        return DslLinkingDiagnosticMessageProvider.class;
    }

    @Override
    public Class<? extends IValueConverterService> bindIValueConverterService() {
        return DslValueConverterService.class;
    }

    public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
        return DslSyntaxErrorMessageProvider.class;
    }
}
