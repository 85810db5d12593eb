package org.miron.bt.resource;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.miron.bt.BtStandaloneSetup;

import com.google.inject.Injector;

/**
 * The EMF resource factory of .bt files, for EMF's {@code extension_parser} extension point (see
 * plugin.xml): in Eclipse, {@code Resource.Factory.Registry.INSTANCE} hands .bt files to the BT
 * language. The language is set up (and registered with EMF and Xtext) on first use.
 */
public final class BtResourceFactory implements Resource.Factory {
    private static Injector injector;

    private static synchronized Injector injector() {
        if (injector == null) {
            injector = new BtStandaloneSetup().createInjectorAndDoEMFRegistration();
        }
        return injector;
    }

    @Override
    public Resource createResource(URI uri) {
        return injector().getInstance(XtextResourceFactory.class).createResource(uri);
    }
}
