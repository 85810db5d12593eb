package org.miron.generator;

import org.eclipse.xtext.generator.GeneratorDelegate;
import org.eclipse.xtext.generator.IGenerator2;

import com.google.inject.AbstractModule;

/**
 * Binds the MIRoN generator for Xtext's generator infrastructure (GeneratorDelegate, builders):
 * {@code MironStandaloneSetup.doSetup().createChildInjector(new MironGeneratorModule())}. The
 * language's own runtime module (org.miron.dsl) does not know the generator, which lives here.
 */
public class MironGeneratorModule extends AbstractModule {
    @Override
    protected void configure() {
        bind(IGenerator2.class).to(MironGenerator.class);
        // Bound here, or Guice would create it just in time in the parent, without the generator.
        bind(GeneratorDelegate.class);
    }
}
