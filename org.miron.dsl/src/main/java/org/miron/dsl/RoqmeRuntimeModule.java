package org.miron.dsl;

import com.google.inject.Binder;

/** Guice bindings of the RoQME language: the generated ones, then those shared with MIRoN. */
public class RoqmeRuntimeModule extends AbstractRoqmeRuntimeModule {

    @Override
    public void configure(Binder binder) {
        DslRuntimeBindings.over(super::configure, binder);
    }
}
