package org.miron.dsl.scoping;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.EObjectDescription;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.MultimapBasedScope;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.eclipse.xtext.util.Tuples;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

import com.google.inject.Inject;

/**
 * Everything a RoQME or MIRoN file can refer to: its own elements unqualified (and prefixed by its
 * own namespace), and the elements of each file it imports directly, prefixed by the import alias,
 * else by that file's namespace, else unqualified. Imported .bt files expose their trees by ID
 * and their nodes by their name attribute, as the BT language exports them.
 * Ambiguous names are kept in the scope and reported by the validator.
 */
public class RoqmeScopeProvider extends AbstractRoqmeScopeProvider {

    @Inject
    private IQualifiedNameProvider nameProvider;

    @Inject
    private IResourceScopeCache cache;

    @Override
    public IScope getScope(EObject context, EReference reference) {
        Resource resource = context.eResource();
        if (resource == null) {
            return IScope.NULLSCOPE;
        }
        // one indexed scope per resource and target type: lookups stay constant-time in big models
        EClass type = reference.getEReferenceType();
        return cache.get(Tuples.pair(RoqmeScopeProvider.class, type), resource, () -> {
            List<IEObjectDescription> matching = new ArrayList<>();
            for (IEObjectDescription d : visible(resource)) {
                if (EcoreUtil2.isAssignableFrom(type, d.getEClass())) {
                    matching.add(d);
                }
            }
            return MultimapBasedScope.createScope(IScope.NULLSCOPE, matching, false);
        });
    }

    /** All descriptions visible in a resource, computed once per resource state. */
    public List<IEObjectDescription> visible(Resource resource) {
        if (resource == null) {
            return List.of();
        }
        return cache.get(Tuples.pair(RoqmeScopeProvider.class, "visible"), resource, () -> compute(resource));
    }

    private List<IEObjectDescription> compute(Resource resource) {
        List<IEObjectDescription> result = new ArrayList<>();
        if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof RoqmeModel)) {
            return result;
        }
        RoqmeModel model = (RoqmeModel) resource.getContents().get(0);
        QualifiedName ownPrefix = model.getNamespace() == null ? null
                : QualifiedName.create(model.getNamespace().split("\\."));
        resource.getAllContents().forEachRemaining(obj -> {
            QualifiedName name = nameProvider.getFullyQualifiedName(obj);
            if (name != null) {
                result.add(EObjectDescription.create(name, obj));
                if (ownPrefix != null) {
                    result.add(EObjectDescription.create(ownPrefix.append(name), obj));
                }
            }
        });
        for (Import imp : model.getImports()) {
            Resource imported = Imports.load(imp);
            if (imported == null) {
                continue;
            }
            QualifiedName prefix = Imports.prefixOf(imp, imported);
            for (IEObjectDescription d : exported(imported)) {
                result.add(EObjectDescription.create(prefix.append(d.getName()), d.getEObjectOrProxy()));
            }
        }
        return result;
    }

    /** The objects a file exports, as its own language names them. */
    private static Iterable<IEObjectDescription> exported(Resource resource) {
        IResourceServiceProvider provider = IResourceServiceProvider.Registry.INSTANCE
                .getResourceServiceProvider(resource.getURI());
        if (provider == null) {
            return List.of();
        }
        IResourceDescription description = provider.getResourceDescriptionManager().getResourceDescription(resource);
        return description.getExportedObjects();
    }
}
