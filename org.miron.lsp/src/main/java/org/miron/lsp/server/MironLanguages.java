package org.miron.lsp.server;

import java.util.concurrent.CompletableFuture;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.Constants;
import org.eclipse.xtext.generator.IShouldGenerate;
import org.eclipse.xtext.ide.server.commands.IExecutableCommandService;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.eclipse.xtext.util.Modules2;
import org.miron.bt.BtRuntimeModule;
import org.miron.bt.BtStandaloneSetup;
import org.miron.bt.ide.BtIdeModule;
import org.miron.bt.ide.BtIdeSetup;
import org.miron.dsl.MironRuntimeModule;
import org.miron.dsl.RoqmeRuntimeModule;
import org.miron.dsl.RoqmeStandaloneSetup;
import org.miron.dsl.ide.MironIdeModule;
import org.miron.dsl.ide.MironIdeSetup;
import org.miron.dsl.ide.RoqmeIdeModule;
import org.miron.dsl.ide.RoqmeIdeSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;
import com.google.inject.Provider;
import com.google.inject.Singleton;
import com.google.inject.name.Names;

/**
 * The languages the server knows, by file extension: .bt and BehaviorTree.CPP .xml trees (see
 * {@link LanguageRegistry}), .roqme and .miron. Each standalone set-up also registers the
 * languages it imports; the ide injectors must be the last ones in EMF's global registries, which
 * the server's resource sets use to load imported files.
 */
@Singleton
public class MironLanguages implements Provider<IResourceServiceProvider.Registry> {
    private IResourceServiceProvider.Registry registry;

    /** Languages being set up ahead of the next server's injector (see {@link #setUpAhead()}). */
    private static CompletableFuture<IResourceServiceProvider.Registry> ahead;

    /**
     * The registry at once, the languages being set up on their own thread (docs/lsp.md, Start-up),
     * so that their set-up overlaps with the rest of the server's start until the client's
     * `initialize` needs them.
     */
    @Override
    public synchronized IResourceServiceProvider.Registry get() {
        if (registry == null) {
            registry = new PendingRegistry(takeAhead());
        }
        return registry;
    }

    /** Starts setting up the languages for the next server, before its injector is even created. */
    static synchronized void setUpAhead() {
        if (ahead == null) {
            ahead = setUpOnItsOwnThread();
            ParserWarmUp.start();
        }
    }

    private static synchronized CompletableFuture<IResourceServiceProvider.Registry> takeAhead() {
        CompletableFuture<IResourceServiceProvider.Registry> languages = ahead != null ? ahead : setUpOnItsOwnThread();
        ahead = null;
        return languages;
    }

    private static CompletableFuture<IResourceServiceProvider.Registry> setUpOnItsOwnThread() {
        CompletableFuture<IResourceServiceProvider.Registry> languages = new CompletableFuture<>();
        Thread setUp = new Thread(() -> {
            try {
                languages.complete(create());
            } catch (Throwable e) {
                languages.completeExceptionally(e);
            }
        }, "miron-lsp-languages");
        setUp.setDaemon(true);
        setUp.start();
        return languages;
    }

    private static IResourceServiceProvider.Registry create() {
        StartupLog.mark("setting up the languages");
        // BT first, then RoQME, then MIRoN, each set-up adopting the injectors of the languages it
        // imports instead of creating runtime-only ones of its own (one injector per language).
        BtServerSetup btSetup = new BtServerSetup();
        Injector bt = btSetup.createInjectorAndDoEMFRegistration();
        BtStandaloneSetup.adopt(bt);
        StartupLog.mark("BT set up");
        RoqmeIdeSetup roqmeSetup = new RoqmeServerSetup();
        Injector roqme = roqmeSetup.createInjectorAndDoEMFRegistration();
        RoqmeStandaloneSetup.adopt(roqme);
        StartupLog.mark("RoQME set up");
        Injector miron = new MironServerSetup().createInjectorAndDoEMFRegistration();
        StartupLog.mark("MIRoN set up");
        // The ide injectors registered last, over any runtime-only one that an earlier set-up in this
        // process (a test's) made and the MIRoN set-up registered again.
        roqmeSetup.register(roqme);
        btSetup.register(bt);
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
                    binder -> binder.bind(IExecutableCommandService.class).to(ConvertCommandService.class),
                    binder -> binder.bind(IShouldGenerate.class).to(NothingToGenerate.class)));
        }
    }

    /** RoQME's ide set-up with the server's builder bindings. */
    private static final class RoqmeServerSetup extends RoqmeIdeSetup {
        @Override
        public Injector createInjector() {
            return Guice.createInjector(Modules2.mixin(new RoqmeRuntimeModule(), new RoqmeIdeModule(),
                    binder -> binder.bind(IShouldGenerate.class).to(NothingToGenerate.class)));
        }
    }

    /** MIRoN's ide set-up plus the services that need the generators (miron.generate). */
    private static final class MironServerSetup extends MironIdeSetup {
        @Override
        public Injector createInjector() {
            return Guice.createInjector(Modules2.mixin(new MironRuntimeModule(), new MironIdeModule(),
                    new MironServerServices(), binder -> binder.bind(IShouldGenerate.class).to(NothingToGenerate.class)));
        }
    }
}
