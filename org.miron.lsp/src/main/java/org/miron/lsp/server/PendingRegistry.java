package org.miron.lsp.server;

import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.IResourceServiceProvider;

/**
 * A language registry whose languages are still being set up: each call waits for them, then asks
 * the real registry. A set-up that failed fails each call with its exception.
 */
final class PendingRegistry implements IResourceServiceProvider.Registry {
    private final CompletableFuture<IResourceServiceProvider.Registry> languages;

    PendingRegistry(CompletableFuture<IResourceServiceProvider.Registry> languages) {
        this.languages = languages;
    }

    private IResourceServiceProvider.Registry languages() {
        try {
            return languages.join();
        } catch (CompletionException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (e.getCause() instanceof Error error) {
                throw error;
            }
            throw e;
        }
    }

    @Override
    public IResourceServiceProvider getResourceServiceProvider(URI uri, String contentType) {
        return languages().getResourceServiceProvider(uri, contentType);
    }

    @Override
    public IResourceServiceProvider getResourceServiceProvider(URI uri) {
        return languages().getResourceServiceProvider(uri);
    }

    @Override
    public Map<String, Object> getContentTypeToFactoryMap() {
        return languages().getContentTypeToFactoryMap();
    }

    @Override
    public Map<String, Object> getExtensionToFactoryMap() {
        return languages().getExtensionToFactoryMap();
    }

    @Override
    public Map<String, Object> getProtocolToFactoryMap() {
        return languages().getProtocolToFactoryMap();
    }
}
