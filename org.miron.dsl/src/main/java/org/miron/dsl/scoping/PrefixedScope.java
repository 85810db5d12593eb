package org.miron.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.impl.AliasedEObjectDescription;
import org.eclipse.xtext.scoping.IScope;
import org.eclipse.xtext.scoping.impl.AbstractScope;
import org.miron.dsl.resource.ModelSummary;

import com.google.common.collect.Iterables;

/**
 * The elements one imported file exports, of one type, named with the import's prefix (alias or
 * namespace; empty for none). Lookups go to the file's index description, by name.
 */
class PrefixedScope extends AbstractScope {

    private final QualifiedName prefix;
    private final IResourceDescription description;
    private final EClass type;

    PrefixedScope(QualifiedName prefix, IResourceDescription description, EClass type, boolean ignoreCase) {
        super(IScope.NULLSCOPE, ignoreCase);
        this.prefix = prefix;
        this.description = description;
        this.type = type;
    }

    @Override
    protected Iterable<IEObjectDescription> getAllLocalElements() {
        return prefixed(description.getExportedObjectsByType(type));
    }

    @Override
    protected Iterable<IEObjectDescription> getLocalElementsByName(QualifiedName name) {
        int n = prefix.getSegmentCount();
        if (name.getSegmentCount() <= n || !startsWithPrefix(name)) {
            return List.of();
        }
        return prefixed(description.getExportedObjects(type, name.skipFirst(n), isIgnoreCase()));
    }

    private boolean startsWithPrefix(QualifiedName name) {
        return isIgnoreCase() ? name.startsWithIgnoreCase(prefix) : name.startsWith(prefix);
    }

    private Iterable<IEObjectDescription> prefixed(Iterable<IEObjectDescription> exported) {
        Iterable<IEObjectDescription> elements = Iterables.filter(exported, d -> !ModelSummary.isSummary(d));
        if (prefix.isEmpty()) {
            return elements;
        }
        return Iterables.transform(elements, d -> new AliasedEObjectDescription(prefix.append(d.getName()), d));
    }
}
