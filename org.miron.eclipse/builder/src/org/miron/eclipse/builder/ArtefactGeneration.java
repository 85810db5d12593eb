package org.miron.eclipse.builder;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.MultiStatus;
import org.eclipse.core.runtime.Status;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

/**
 * A .miron model's artefacts into generated/ beside it, as `miron generate FILE -o generated`
 * writes them (the same BatchGeneration with its defaults, so the same bytes): all or nothing, a
 * model with errors writes nothing. The folder is refreshed and marked derived (it is output, not
 * source). The builder and the Generate command both call this.
 */
public final class ArtefactGeneration {
    public static final String FOLDER = "generated";
    static final String BUNDLE = "org.miron.eclipse";

    private ArtefactGeneration() {
    }

    /** The folder a model generates into. */
    public static IFolder folderOf(IFile model) {
        return model.getParent().getFolder(new org.eclipse.core.runtime.Path(FOLDER));
    }

    /** Generates one model; OK, or an error status listing the model's errors. */
    public static IStatus generate(IFile model) {
        IFolder folder = folderOf(model);
        BatchGeneration.Outcome outcome;
        try {
            ModelLoader loader = new ModelLoader();
            var resource = loader.load(ModelFiles.toFile(model));
            outcome = new BatchGeneration(loader, WeightPolicy.NEED)
                    .run(List.of(resource), BatchGeneration.folder(folder.getLocation().toFile().toPath()));
        } catch (RuntimeException e) {
            return new Status(IStatus.ERROR, BUNDLE, "Not generated: " + model.getName() + ": " + e, e);
        }
        if (!outcome.written().isEmpty()) {
            refresh(folder);
        }
        if (outcome.succeeded()) {
            return new Status(IStatus.OK, BUNDLE, "Generated " + String.join(", ", outcome.written()));
        }
        List<Diagnostic> errors = new ArrayList<>(outcome.generationErrors());
        outcome.validation().stream().filter(d -> d.severity() == Diagnostic.Severity.ERROR).forEach(errors::add);
        String message = outcome.stage() == BatchGeneration.Stage.WRITE_FAILED
                ? "Not all written: " + folder.getFullPath() + ": " + outcome.writeError()
                : "Not generated: " + model.getName() + " has " + errors.size() + (errors.size() == 1 ? " error" : " errors");
        MultiStatus status = new MultiStatus(BUNDLE, 0, message, null);
        errors.forEach(d -> status.add(new Status(IStatus.ERROR, BUNDLE, d.toString())));
        if (errors.isEmpty()) {
            return new Status(IStatus.ERROR, BUNDLE, message);
        }
        return status;
    }

    private static void refresh(IFolder folder) {
        try {
            folder.refreshLocal(IResource.DEPTH_INFINITE, null);
            if (folder.exists() && !folder.isDerived()) {
                folder.setDerived(true, null);
            }
        } catch (CoreException e) {
            // The files are on disk; the workspace sees them at its next refresh.
        }
    }
}
