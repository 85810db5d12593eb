package org.miron.eclipse.builder;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;

import org.eclipse.core.resources.IFile;

/**
 * Which model files each checked file loaded (its imports, transitively), so that a change to one
 * file re-checks every file that imports it. Kept by the builder for the session; an empty graph
 * (a new session) makes the next build a full one.
 */
final class ImportGraph {
    private final Map<IFile, Set<IFile>> imports = new HashMap<>();

    boolean isEmpty() {
        return imports.isEmpty();
    }

    void clear() {
        imports.clear();
    }

    void put(IFile file, Set<IFile> loaded) {
        Set<IFile> others = new LinkedHashSet<>(loaded);
        others.remove(file);
        imports.put(file, others);
    }

    void remove(IFile file) {
        imports.remove(file);
    }

    /** The files that import any of the given ones (directly or not). */
    Set<IFile> importersOf(Set<IFile> changed) {
        Set<IFile> importers = new LinkedHashSet<>();
        imports.forEach((file, loaded) -> {
            if (loaded.stream().anyMatch(changed::contains)) {
                importers.add(file);
            }
        });
        return importers;
    }
}
