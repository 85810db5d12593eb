package org.miron.dsl.ide;

import com.google.inject.Binder;
import com.google.inject.util.Modules;

/** Guice bindings of the RoQME language's ide services: the generated ones, then those shared with MIRoN. */
public class RoqmeIdeModule extends AbstractRoqmeIdeModule {

    @Override
    public void configure(Binder binder) {
        Modules.override(super::configure).with(new DslIdeBindings()).configure(binder);
    }
}
