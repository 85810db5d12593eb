package org.miron.bt;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.linking.ILinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.scoping.IGlobalScopeProvider;
import org.miron.bt.conversion.BtValueConverterService;
import org.miron.bt.formatting2.BtFormatter;
import org.miron.bt.linking.BtLinkingDiagnosticMessageProvider;
import org.miron.bt.naming.BtQualifiedNameProvider;
import org.miron.bt.scoping.BtGlobalScopeProvider;

/** Guice bindings of the BT language's runtime services. */
public class BtRuntimeModule extends AbstractBtRuntimeModule {

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

    public Class<? extends ILinkingDiagnosticMessageProvider> bindILinkingDiagnosticMessageProvider() {
        return BtLinkingDiagnosticMessageProvider.class;
    }
}
