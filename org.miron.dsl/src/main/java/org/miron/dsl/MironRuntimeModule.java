package org.miron.dsl;

import com.google.inject.Binder;

/** Guice bindings of the MIRoN language: the generated ones, then those shared with RoQME. */
public class MironRuntimeModule extends AbstractMironRuntimeModule {

    @Override
    public void configure(Binder binder) {
        DslRuntimeBindings.over(super::configure, binder);
    }
}
