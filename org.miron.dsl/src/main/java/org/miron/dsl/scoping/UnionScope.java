package org.miron.dsl.scoping;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScope;

import com.google.common.collect.Iterables;

/**
 * Several scopes side by side, none shadowing another: a name found in two of them yields both
 * elements, so that the validator can report it as ambiguous. The first one wins for linking.
 */
class UnionScope implements IScope {

    private final List<IScope> scopes;

    UnionScope(List<IScope> scopes) {
        this.scopes = List.copyOf(scopes);
    }

    @Override
    public IEObjectDescription getSingleElement(QualifiedName name) {
        for (IScope scope : scopes) {
            IEObjectDescription found = scope.getSingleElement(name);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    @Override
    public Iterable<IEObjectDescription> getElements(QualifiedName name) {
        return Iterables.concat(Iterables.transform(scopes, s -> s.getElements(name)));
    }

    @Override
    public IEObjectDescription getSingleElement(EObject object) {
        for (IScope scope : scopes) {
            IEObjectDescription found = scope.getSingleElement(object);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    @Override
    public Iterable<IEObjectDescription> getElements(EObject object) {
        return Iterables.concat(Iterables.transform(scopes, s -> s.getElements(object)));
    }

    @Override
    public Iterable<IEObjectDescription> getAllElements() {
        return Iterables.concat(Iterables.transform(scopes, IScope::getAllElements));
    }
}
