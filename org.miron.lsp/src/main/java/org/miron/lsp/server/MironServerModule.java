package org.miron.lsp.server;

import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.xtext.ide.server.ILanguageServerShutdownAndExitHandler;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.ServerModule;
import org.eclipse.xtext.ide.server.concurrent.IRequestManager;
import org.eclipse.xtext.ide.server.concurrent.RequestManager;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.util.IFileSystemScanner;

import com.google.inject.AbstractModule;
import com.google.inject.Module;
import com.google.inject.util.Modules;

/** Xtext's language-server bindings with the MIRoN languages registered explicitly (not by service loading). */
public final class MironServerModule {

    private MironServerModule() {
    }

    /**
     * @param exitProcess whether the client's `exit` ends the process (stdio: the client owns the
     *        process) or only its connection (socket server, tests in the same JVM)
     */
    public static Module create(boolean exitProcess) {
        return Modules.override(new ServerModule()).with(new AbstractModule() {
            @Override
            protected void configure() {
                bind(IResourceServiceProvider.Registry.class).toProvider(MironLanguages.class);
                bind(LanguageServer.class).to(MironLanguageServerImpl.class);
                bind(LanguageServerImpl.class).to(MironLanguageServerImpl.class);
                bind(IRequestManager.class).to(GuardedRequestManager.class);
                bind(RequestManager.class).to(GuardedRequestManager.class);
                bind(IFileSystemScanner.class).to(BoundedFileSystemScanner.class);
                if (!exitProcess) {
                    bind(ILanguageServerShutdownAndExitHandler.class).to(ILanguageServerShutdownAndExitHandler.NullImpl.class);
                }
            }
        });
    }
}
