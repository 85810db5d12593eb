package org.miron.dsl.scoping;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EcorePackage;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.AbstractGlobalScopeProvider;
import org.eclipse.xtext.scoping.impl.FilteringScope;
import org.miron.dsl.resource.ModelSummary;
import org.miron.dsl.util.Imports;

import com.google.common.base.Predicate;
import com.google.inject.Inject;

/**
 * What a RoQME/MIRoN file sees of the files it imports directly, read from the index: each
 * import's exported elements prefixed by its alias, else by the imported model's namespace (from
 * its {@link ModelSummary}), else unprefixed. Imports do not shadow each other (see
 * {@link UnionScope}). The linker records the names looked up here as the file's imported names.
 */
public class DslGlobalScopeProvider extends AbstractGlobalScopeProvider {

    @Inject
    private ImportedResources importedResources;

    @Override
    protected IScope getScope(Resource resource, boolean ignoreCase, EClass type,
            Predicate<IEObjectDescription> filter) {
        List<IScope> scopes = new ArrayList<>();
        for (ImportedResources.Resolved imported : importedResources.of(resource)) {
            QualifiedName prefix = Imports.prefixOf(imported.imp(), ModelSummary.namespace(imported.description()));
            IScope scope = new PrefixedScope(prefix, imported.description(), type, ignoreCase);
            scopes.add(filter == null ? scope : new FilteringScope(scope, filter));
        }
        return scopes.isEmpty() ? IScope.NULLSCOPE : new UnionScope(scopes);
    }

    /** Every imported element of any type, as named in the file (for messages). */
    public Iterable<IEObjectDescription> allImported(Resource resource) {
        return getScope(resource, false, EcorePackage.Literals.EOBJECT, null).getAllElements();
    }
}
