package org.miron.dsl.resource;

import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Deque;
import java.util.HashSet;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.IResourceDescription.Delta;
import org.eclipse.xtext.resource.IResourceDescriptions;
import org.eclipse.xtext.resource.impl.DefaultResourceDescriptionManager;

import com.google.inject.Singleton;

/**
 * Tells an incremental builder which RoQME/MIRoN files to revalidate: those importing a changed
 * .bt, .roqme or .miron file, directly or through the files they import (an imported model's
 * types come from its own imports). Imports are read from the index ({@link ModelSummary}), so no
 * candidate is loaded. Any change counts, not only changed names: a binding's XPath or a
 * variable's type depends on more than what a file exports.
 */
@Singleton
public class DslResourceDescriptionManager extends DefaultResourceDescriptionManager
        implements IResourceDescription.Manager.AllChangeAware {

    @Override
    public boolean isAffected(Collection<Delta> deltas, IResourceDescription candidate, IResourceDescriptions context) {
        return importsAny(deltas, candidate, context) || super.isAffected(deltas, candidate, context);
    }

    /** Without an index at hand only direct imports are known. */
    @Override
    public boolean isAffected(Delta delta, IResourceDescription candidate) {
        return ModelSummary.imports(candidate).contains(delta.getUri()) || super.isAffected(delta, candidate);
    }

    @Override
    public boolean isAffectedByAny(Collection<Delta> deltas, IResourceDescription candidate,
            IResourceDescriptions context) {
        return isAffected(deltas, candidate, context);
    }

    private static boolean importsAny(Collection<Delta> deltas, IResourceDescription candidate,
            IResourceDescriptions context) {
        Set<URI> changed = new HashSet<>();
        for (Delta delta : deltas) {
            changed.add(delta.getUri());
        }
        Set<URI> seen = new HashSet<>();
        seen.add(candidate.getURI());
        Deque<IResourceDescription> pending = new ArrayDeque<>();
        pending.add(candidate);
        while (!pending.isEmpty()) {
            for (URI imported : ModelSummary.imports(pending.poll())) {
                if (changed.contains(imported)) {
                    return true;
                }
                IResourceDescription next = seen.add(imported) ? context.getResourceDescription(imported) : null;
                if (next != null) {
                    pending.add(next);
                }
            }
        }
        return false;
    }
}
