package org.miron.dsl.ide;

import com.google.inject.Binder;
import com.google.inject.util.Modules;

/** Guice bindings of the MIRoN language's ide services: the generated ones, then those shared with RoQME. */
public class MironIdeModule extends AbstractMironIdeModule {

    @Override
    public void configure(Binder binder) {
        Modules.override(super::configure).with(new DslIdeBindings()).configure(binder);
    }
}
