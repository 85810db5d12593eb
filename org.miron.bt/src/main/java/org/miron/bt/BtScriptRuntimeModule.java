package org.miron.bt;

import org.eclipse.xtext.conversion.IValueConverterService;
import org.miron.bt.script.ScriptValueConverterService;

/** Guice bindings of the scripting language's runtime services. */
public class BtScriptRuntimeModule extends AbstractBtScriptRuntimeModule {

    @Override
    public Class<? extends IValueConverterService> bindIValueConverterService() {
        return ScriptValueConverterService.class;
    }
}
