package org.miron.dsl.util;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.naming.QualifiedName;
import org.miron.dsl.roqme.Import;

/** Where an import points and under which prefix its elements are visible. */
public final class Imports {

    private Imports() {
    }

    /** The import path resolved against the importing file, or null when it is not a URI. */
    public static URI uriOf(Import imp) {
        String path = imp.getImportURI();
        if (path == null || path.isEmpty()) {
            return null;
        }
        try {
            URI uri = URI.createURI(path);
            Resource here = imp.eResource();
            return here != null && here.getURI() != null && uri.isRelative() ? uri.resolve(here.getURI()) : uri;
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    /**
     * The imported file loaded into the importer's resource set, or null when it cannot be read.
     * For generators, which need the imported model itself; scoping and validation read imports
     * from the index instead (scoping/ImportedResources).
     */
    public static Resource load(Import imp) {
        URI uri = uriOf(imp);
        Resource here = imp.eResource();
        if (uri == null || here == null || uri.equals(here.getURI())) {
            return null;
        }
        try {
            if (!EcoreUtil2.isValidUri(here, uri)) {
                return null;
            }
            Resource resource = EcoreUtil2.getResource(here, uri.toString());
            return resource == null || resource.getContents().isEmpty() ? null : resource;
        } catch (RuntimeException e) {
            // unreadable or unknown file type: reported by the validator, never thrown at the user
            return null;
        }
    }

    /** alias if given, else the imported model's namespace, else nothing (unqualified). */
    public static QualifiedName prefixOf(Import imp, String importedNamespace) {
        String alias = aliasOf(imp);
        if (alias != null && !alias.isEmpty()) {
            return QualifiedName.create(alias);
        }
        if (importedNamespace != null) {
            return QualifiedName.create(importedNamespace.split("\\."));
        }
        return QualifiedName.EMPTY;
    }

    public static String aliasOf(Import imp) {
        return imp instanceof org.miron.dsl.miron.Import ? ((org.miron.dsl.miron.Import) imp).getAlias() : null;
    }
}
