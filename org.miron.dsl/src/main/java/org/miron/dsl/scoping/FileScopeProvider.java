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
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.AbstractGlobalScopeDelegatingScopeProvider;
import org.eclipse.xtext.scoping.impl.MultimapBasedScope;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.eclipse.xtext.util.Tuples;
import org.miron.dsl.roqme.RoqmeModel;

import com.google.common.collect.Iterables;
import com.google.inject.Inject;

/**
 * Everything a RoQME or MIRoN file can refer to: its own elements, unqualified and prefixed by its
 * own namespace, side by side with what the global scope provider gives of its imports (see
 * {@link DslGlobalScopeProvider}). The imported part goes through the global scope so that the
 * linker records the names it looks up there.
 */
public class FileScopeProvider extends AbstractGlobalScopeDelegatingScopeProvider {

    @Inject
    private IQualifiedNameProvider nameProvider;

    @Inject
    private IResourceScopeCache cache;

    @Inject
    private DslGlobalScopeProvider globalScopeProvider;

    @Override
    public IScope getScope(EObject context, EReference reference) {
        Resource resource = context.eResource();
        if (resource == null) {
            return IScope.NULLSCOPE;
        }
        return new UnionScope(List.of(local(resource, reference.getEReferenceType()), getGlobalScope(resource, reference)));
    }

    /** All descriptions visible in a resource, own and imported, of any type. */
    public List<IEObjectDescription> visible(Resource resource) {
        if (resource == null) {
            return List.of();
        }
        List<IEObjectDescription> result = new ArrayList<>(own(resource));
        Iterables.addAll(result, globalScopeProvider.allImported(resource));
        return result;
    }

    /** The file's own elements of one type, indexed once per resource state: big models stay fast. */
    private IScope local(Resource resource, EClass type) {
        return cache.get(Tuples.pair(FileScopeProvider.class, type), resource, () -> {
            List<IEObjectDescription> matching = new ArrayList<>();
            for (IEObjectDescription d : own(resource)) {
                if (EcoreUtil2.isAssignableFrom(type, d.getEClass())) {
                    matching.add(d);
                }
            }
            return MultimapBasedScope.createScope(IScope.NULLSCOPE, matching, false);
        });
    }

    private List<IEObjectDescription> own(Resource resource) {
        return cache.get(Tuples.pair(FileScopeProvider.class, "own"), resource, () -> {
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
            return result;
        });
    }
}
