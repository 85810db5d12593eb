package org.miron.eclipse.builder;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.core.resources.IFile;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

/**
 * One model file checked as `miron check FILE` checks it: loaded with everything it imports into a
 * fresh {@link ModelLoader}, all of them validated with every check. Answers the diagnostics and the
 * workspace files that were loaded (the file's own imports, transitively: the builder's dependency
 * graph is made of these). A parser or linker that throws gives one error on the file instead.
 */
record ModelCheck(IFile root, Set<IFile> loaded, List<Diagnostic> diagnostics) {

    static ModelCheck of(IFile root) {
        ModelLoader loader = new ModelLoader();
        try {
            loader.load(ModelFiles.toFile(root));
            List<Diagnostic> diagnostics = loader.validateAll();
            Set<IFile> loaded = new LinkedHashSet<>();
            loaded.add(root);
            for (Resource resource : loader.resourceSet().getResources()) {
                if (resource.getURI().isFile()) {
                    IFile file = ModelFiles.fromPath(resource.getURI().toFileString());
                    if (file != null) {
                        loaded.add(file);
                    }
                }
            }
            return new ModelCheck(root, loaded, diagnostics);
        } catch (RuntimeException e) {
            // Never an exception in the Error Log for a bad file: one marker says what happened.
            Diagnostic failure = new Diagnostic(ModelFiles.toFile(root).getPath(), 1, 1, Diagnostic.Severity.ERROR,
                    "cannot read this model: " + e);
            return new ModelCheck(root, Set.of(root), List.of(failure));
        }
    }

    /** True when neither the file nor anything it imports has an error. */
    boolean valid() {
        return diagnostics.stream().noneMatch(d -> d.severity() == Diagnostic.Severity.ERROR);
    }
}
