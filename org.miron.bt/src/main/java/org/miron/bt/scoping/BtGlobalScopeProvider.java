package org.miron.bt.scoping;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.scoping.impl.ImportUriGlobalScopeProvider;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.Import;
import org.miron.bt.resource.BtXmlFiles;

/**
 * Trees visible from a file: those of every file it includes, transitively, as BehaviorTree.CPP
 * loads includes recursively. Include paths are relative to the including file.
 */
public class BtGlobalScopeProvider extends ImportUriGlobalScopeProvider {

    @Override
    protected LinkedHashSet<URI> getImportedUris(Resource resource) {
        LinkedHashSet<URI> result = new LinkedHashSet<>();
        Deque<Resource> pending = new ArrayDeque<>();
        pending.add(resource);
        while (!pending.isEmpty()) {
            Resource current = pending.poll();
            for (URI uri : includesOf(current)) {
                if (uri.equals(resource.getURI()) || !result.add(uri)) {
                    continue;
                }
                Resource included = EcoreUtil2.getResource(resource, uri.toString());
                if (!BtXmlFiles.isTree(included)) {
                    // not a BT file (e.g. an .xml of another kind): nothing to see, the validator says so
                    result.remove(uri);
                } else {
                    pending.add(included);
                }
            }
        }
        return result;
    }

    /** Absolute URIs of the files a resource includes directly (those that exist). */
    public static LinkedHashSet<URI> includesOf(Resource resource) {
        LinkedHashSet<URI> uris = new LinkedHashSet<>();
        if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            return uris;
        }
        for (Import include : ((BTModel) resource.getContents().get(0)).getImports()) {
            URI uri = resolve(resource, include.getImportURI());
            if (uri != null && EcoreUtil2.isValidUri(resource, uri)) {
                uris.add(uri);
            }
        }
        return uris;
    }

    /** An include path resolved against the including file, or null when it is not a URI. */
    public static URI resolve(Resource resource, String path) {
        if (path == null || path.isEmpty()) {
            return null;
        }
        try {
            URI uri = URI.createURI(path);
            return resource.getURI() != null && uri.isRelative() ? uri.resolve(resource.getURI()) : uri;
        } catch (IllegalArgumentException e) {
            return null;
        }
    }
}
