package org.miron.dsl.scoping;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.IResourceDescriptionsProvider;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.scoping.impl.LoadOnDemandResourceDescriptions;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

import com.google.inject.Inject;
import com.google.inject.Provider;

/**
 * The files a RoQME/MIRoN model imports, as the index of its resource set describes them: in a
 * builder or editor that is the workspace index (with unsaved content); standalone, where the
 * index is the resource set itself, a file not loaded yet is loaded on demand.
 */
public class ImportedResources {

    /** An import and the description of the file it names. */
    public record Resolved(Import imp, URI uri, IResourceDescription description) {
    }

    @Inject
    private IResourceDescriptionsProvider indexProvider;

    @Inject
    private Provider<LoadOnDemandResourceDescriptions> loadOnDemand;

    @Inject
    private IResourceServiceProvider.Registry languages;

    @Inject
    private IResourceScopeCache cache;

    /** The imports of a resource whose file can be found, in import order. */
    public List<Resolved> of(Resource resource) {
        List<Resolved> result = new ArrayList<>();
        if (resource == null || resource.getContents().isEmpty()
                || !(resource.getContents().get(0) instanceof RoqmeModel)) {
            return result;
        }
        IResourceDescriptions index = indexProvider.getResourceDescriptions(resource.getResourceSet());
        for (Import imp : imports(resource)) {
            URI uri = Imports.uriOf(imp);
            IResourceDescription description = describe(index, resource, uri);
            if (description != null) {
                result.add(new Resolved(imp, uri, description));
            }
        }
        return result;
    }

    /**
     * The model's imports, kept until the resource changes: every global scope asks for them, and
     * the derived {@code getImports()} walks all sentences (quadratic on a 5 000-sentence model).
     * Only what the resource itself says is cached; the imported files' descriptions are read from
     * the index on every call, so that a changed import is seen at once.
     */
    private List<Import> imports(Resource resource) {
        return cache.get(ImportedResources.class, resource,
                () -> ((RoqmeModel) resource.getContents().get(0)).getImports());
    }

    /** The description of the imported file, or null when it cannot be found or read. */
    public IResourceDescription description(Import imp) {
        Resource resource = imp.eResource();
        if (resource == null || resource.getResourceSet() == null) {
            return null;
        }
        IResourceDescriptions index = indexProvider.getResourceDescriptions(resource.getResourceSet());
        return describe(index, resource, Imports.uriOf(imp));
    }

    private IResourceDescription describe(IResourceDescriptions index, Resource resource, URI uri) {
        if (uri == null || uri.equals(resource.getURI()) || languages.getResourceServiceProvider(uri) == null) {
            return null;
        }
        try {
            IResourceDescription indexed = index.getResourceDescription(uri);
            if (indexed != null || !EcoreUtil2.isValidUri(resource, uri)) {
                return indexed;
            }
            LoadOnDemandResourceDescriptions loading = loadOnDemand.get();
            loading.initialize(index, List.of(uri), resource);
            return loading.getResourceDescription(uri);
        } catch (RuntimeException e) {
            // unreadable file: the validator reports the import, nothing is thrown at the user
            return null;
        }
    }
}
