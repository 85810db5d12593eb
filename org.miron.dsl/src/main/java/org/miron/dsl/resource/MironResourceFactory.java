package org.miron.dsl.resource;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.miron.dsl.MironStandaloneSetup;

import com.google.inject.Injector;

/**
 * The EMF resource factory of .miron files, for EMF's {@code extension_parser} extension point (see
 * plugin.xml): in Eclipse, {@code Resource.Factory.Registry.INSTANCE} hands these files to the
 * Miron language. The language is set up (and registered with EMF and Xtext) on first use.
 */
public final class MironResourceFactory implements Resource.Factory {
    private static Injector injector;

    private static synchronized Injector injector() {
        if (injector == null) {
            injector = new MironStandaloneSetup().createInjectorAndDoEMFRegistration();
        }
        return injector;
    }

    @Override
    public Resource createResource(URI uri) {
        return injector().getInstance(XtextResourceFactory.class).createResource(uri);
    }
}
