package org.miron.dsl;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.formatting2.FormatterPreferenceValuesProvider;
import org.eclipse.xtext.formatting2.FormatterPreferences;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.eclipse.xtext.preferences.IPreferenceValuesProvider;
import org.miron.dsl.conversion.DslValueConverterService;
import org.miron.dsl.formatting2.DslFormatter;
import org.miron.dsl.linking.DslLinkingDiagnosticMessageProvider;
import org.miron.dsl.naming.DslQualifiedNameConverter;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.parser.DslSyntaxErrorMessageProvider;

import com.google.inject.Binder;

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

    public Class<? extends IFormatter2> bindIFormatter2() {
        return DslFormatter.class;
    }

    public void configureFormatterPreferences(Binder binder) {
        binder.bind(IPreferenceValuesProvider.class).annotatedWith(FormatterPreferences.class)
                .to(FormatterPreferenceValuesProvider.class);
    }
}
