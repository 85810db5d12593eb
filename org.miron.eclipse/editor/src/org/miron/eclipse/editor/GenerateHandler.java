package org.miron.eclipse.editor;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.expressions.IEvaluationContext;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.Adapters;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.MultiStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.jobs.Job;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * "Generate MIRoN artefacts" on the selected .miron files (or the .miron file of the active
 * editor): a job per file asks the MIRoN language server's {@code miron.generate} for the saved
 * file (the server writes the woven tree, MiniZinc model and data and io.json into generated/ next
 * to the model, or nothing when the model has errors) and refreshes the folder. A failure ends the
 * job with an error status (shown by the workbench) listing the errors.
 */
public final class GenerateHandler extends AbstractHandler {
    /** Jobs of this handler belong to this family (tests wait for them). */
    public static final Object FAMILY = GenerateHandler.class;

    @Override
    public Object execute(ExecutionEvent event) {
        for (IFile file : mironFiles(event.getApplicationContext())) {
            Job job = new Job("Generating MIRoN artefacts for " + file.getName()) {
                @Override
                protected IStatus run(org.eclipse.core.runtime.IProgressMonitor monitor) {
                    return generate(file);
                }

                @Override
                public boolean belongsTo(Object family) {
                    return family == FAMILY;
                }
            };
            job.setRule(file.getParent());
            job.setUser(true);
            job.schedule();
        }
        return null;
    }

    /** The .miron files of the selection, else the active editor's file. */
    static List<IFile> mironFiles(Object applicationContext) {
        Set<IFile> files = new LinkedHashSet<>();
        if (applicationContext instanceof IEvaluationContext context) {
            Object selection = context.getVariable("selection");
            Iterable<?> elements = selection instanceof Iterable<?> iterable ? iterable : List.of();
            for (Object element : elements) {
                addIfMiron(files, element);
            }
            if (files.isEmpty()) {
                addIfMiron(files, context.getVariable("activeEditorInput"));
            }
        }
        return new ArrayList<>(files);
    }

    private static void addIfMiron(Set<IFile> files, Object element) {
        IFile file = element == null ? null : Adapters.adapt(element, IFile.class);
        if (file != null && "miron".equals(file.getFileExtension()) && file.getLocation() != null) {
            files.add(file);
        }
    }

    /** Generates one file through the language server; the job's status. */
    public static IStatus generate(IFile file) {
        String plugin = "org.miron.eclipse.editor";
        Path model = file.getLocation().toFile().toPath();
        JsonObject answer;
        try (ServerSession server = new ServerSession(file.getProject().getLocation().toFile().toPath())) {
            answer = server.generate(model);
        } catch (Exception e) {
            return new Status(IStatus.ERROR, plugin, "MIRoN language server: " + e.getMessage(), e);
        }
        try {
            file.getParent().refreshLocal(IResource.DEPTH_INFINITE, null);
        } catch (CoreException e) {
            // The files are written; the workspace will see them on the next refresh.
        }
        String message = answer.get("message").getAsString();
        if (answer.get("ok").getAsBoolean()) {
            return new Status(IStatus.OK, plugin, message);
        }
        if (answer.getAsJsonArray("errors").isEmpty()) {
            return new Status(IStatus.ERROR, plugin, message);
        }
        MultiStatus status = new MultiStatus(plugin, 0, message, null);
        for (JsonElement error : answer.getAsJsonArray("errors")) {
            status.add(new Status(IStatus.ERROR, plugin, error.getAsString()));
        }
        return status;
    }
}
