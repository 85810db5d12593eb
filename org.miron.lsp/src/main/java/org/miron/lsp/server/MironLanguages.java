package org.miron.lsp.server;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.Constants;
import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.eclipse.xtext.util.Modules2;
import org.miron.bt.BtRuntimeModule;
import org.miron.bt.ide.BtIdeModule;
import org.miron.bt.ide.BtIdeSetup;
import org.miron.dsl.MironRuntimeModule;
import org.miron.dsl.ide.MironIdeModule;
import org.miron.dsl.ide.MironIdeSetup;
import org.miron.dsl.ide.RoqmeIdeSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;
import com.google.inject.Provider;
import com.google.inject.Singleton;
import com.google.inject.name.Names;

/**
 * The languages the server knows, by file extension: .bt and BehaviorTree.CPP .xml trees (see
 * {@link LanguageRegistry}), .roqme and .miron. Set up in this order because each standalone
 * set-up also registers the languages it imports with their runtime-only injectors: the ide
 * injectors must be the last ones in EMF's global registries, which the server's resource sets
 * use to load imported files.
 */
@Singleton
public class MironLanguages implements Provider<IResourceServiceProvider.Registry> {
    private IResourceServiceProvider.Registry registry;

    @Override
    public synchronized IResourceServiceProvider.Registry get() {
        if (registry == null) {
            registry = create();
        }
        return registry;
    }

    private static IResourceServiceProvider.Registry create() {
        Injector miron = new MironServerSetup().createInjectorAndDoEMFRegistration();
        Injector roqme = new RoqmeIdeSetup().createInjectorAndDoEMFRegistration();
        Injector bt = new BtServerSetup().createInjectorAndDoEMFRegistration();
        // Woven trees (name.ext.xml) and other BehaviorTree.CPP XML files are BT files (LanguageRegistry).
        IResourceServiceProvider btServices = bt.getInstance(IResourceServiceProvider.class);
        IResourceServiceProvider.Registry.INSTANCE.getExtensionToFactoryMap().put("xml", btServices);
        Resource.Factory.Registry.INSTANCE.getExtensionToFactoryMap()
                .put("xml", bt.getInstance(XtextResourceFactory.class));

        LanguageRegistry result = new LanguageRegistry();
        result.getExtensionToFactoryMap().put("bt", btServices);
        result.getExtensionToFactoryMap().put("xml", btServices);
        result.getExtensionToFactoryMap().put("roqme", roqme.getInstance(IResourceServiceProvider.class));
        result.getExtensionToFactoryMap().put("miron", miron.getInstance(IResourceServiceProvider.class));
        return result;
    }

    /**
     * BT's ide set-up where .xml is a BT extension too: Xtext's builder only builds (and so only
     * validates and publishes diagnostics for) files whose extension the language declares. Its
     * command is miron.convert.
     */
    private static final class BtServerSetup extends BtIdeSetup {
        @Override
        public Injector createInjector() {
            return Guice.createInjector(Modules2.mixin(new BtRuntimeModule(), new BtIdeModule(),
                    binder -> binder.bind(String.class).annotatedWith(Names.named(Constants.FILE_EXTENSIONS))
                            .toInstance("bt,xml"),
                    binder -> binder.bind(IExecutableCommandService.class).to(ConvertCommandService.class)));
        }
    }

    /** MIRoN's ide set-up plus the services that need the generators (miron.generate). */
    private static final class MironServerSetup extends MironIdeSetup {
        @Override
        public Injector createInjector() {
            return Guice.createInjector(Modules2.mixin(new MironRuntimeModule(), new MironIdeModule(),
                    new MironServerServices()));
        }
    }
}
