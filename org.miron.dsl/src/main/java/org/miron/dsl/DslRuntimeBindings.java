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
import org.eclipse.xtext.resource.IDefaultResourceDescriptionStrategy;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.scoping.IGlobalScopeProvider;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.scoping.impl.AbstractDeclarativeScopeProvider;
import org.eclipse.xtext.service.AbstractGenericModule;
import org.miron.dsl.conversion.DslValueConverterService;
import org.miron.dsl.formatting2.DslFormatter;
import org.miron.dsl.linking.DslLinkingDiagnosticMessageProvider;
import org.miron.dsl.naming.DslQualifiedNameConverter;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.parser.DslSyntaxErrorMessageProvider;
import org.miron.dsl.resource.DslResourceDescriptionManager;
import org.miron.dsl.resource.DslResourceDescriptionStrategy;
import org.miron.dsl.scoping.DslGlobalScopeProvider;
import org.miron.dsl.scoping.FileScopeProvider;

import com.google.inject.Binder;
import com.google.inject.Module;
import com.google.inject.name.Names;
import com.google.inject.util.Modules;

/**
 * The services RoQME and MIRoN share: names, imports through the index, messages, formatting.
 * MIRoN's generated module does not extend RoQME's, so both runtime modules apply these over
 * their generated bindings ({@link #over}) instead of repeating them.
 */
public class DslRuntimeBindings extends AbstractGenericModule {

    /** Configures the generated bindings with these in place of any they also bind. */
    public static void over(Module generated, Binder binder) {
        Modules.override(generated).with(new DslRuntimeBindings()).configure(binder);
    }

    public Class<? extends IQualifiedNameProvider> bindIQualifiedNameProvider() {
        return DslQualifiedNameProvider.class;
    }

    public Class<? extends IQualifiedNameConverter> bindIQualifiedNameConverter() {
        return DslQualifiedNameConverter.class;
    }

    public void configureIScopeProviderDelegate(Binder binder) {
        binder.bind(IScopeProvider.class).annotatedWith(Names.named(AbstractDeclarativeScopeProvider.NAMED_DELEGATE))
                .to(FileScopeProvider.class);
    }

    public Class<? extends IGlobalScopeProvider> bindIGlobalScopeProvider() {
        return DslGlobalScopeProvider.class;
    }

    public Class<? extends IDefaultResourceDescriptionStrategy> bindIDefaultResourceDescriptionStrategy() {
        return DslResourceDescriptionStrategy.class;
    }

    public Class<? extends IResourceDescription.Manager> bindIResourceDescription$Manager() {
        return DslResourceDescriptionManager.class;
    }

    public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
        return DslLinkingDiagnosticMessageProvider.class;
    }

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
