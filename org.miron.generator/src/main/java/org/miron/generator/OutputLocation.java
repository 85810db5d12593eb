package org.miron.generator;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.IFileSystemAccess2;

/** Where a generated file will live, as a URI: the base for relative paths written into it. */
final class OutputLocation {
    private OutputLocation() {
    }

    /**
     * The target's URI of fileName (file:, platform:/resource, memory:/DEFAULT_OUTPUT/ for the
     * in-memory access...); a target that gives no absolute URI is taken to write beside the model.
     */
    static URI of(IFileSystemAccess2 target, String fileName, Resource model) {
        URI uri = target.getURI(fileName);
        if (uri != null && uri.isHierarchical() && !uri.isRelative()) {
            return uri;
        }
        return URI.createURI(fileName).resolve(model.getURI());
    }

    /**
     * uri as a path relative to the file at base ("../models/lib/extra.bt"), computed on URIs so
     * it works for any scheme; absolute when the two do not share scheme and authority.
     */
    static String relative(URI uri, URI base) {
        return URI.decode(uri.deresolve(base, true, true, false).toString());
    }
}
