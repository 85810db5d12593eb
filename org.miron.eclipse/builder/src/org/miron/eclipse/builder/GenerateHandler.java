package org.miron.eclipse.builder;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.jobs.Job;

/**
 * "Generate MIRoN artefacts" on the selected .miron files (or the active editor's): a job per file
 * runs {@link ArtefactGeneration}, the builder's own generation; a model with errors ends its job
 * with an error status (shown by the workbench) listing them.
 */
public final class GenerateHandler extends AbstractHandler {
    /** Jobs of this handler belong to this family (tests wait for them). */
    public static final Object FAMILY = GenerateHandler.class;

    @Override
    public Object execute(ExecutionEvent event) {
        for (IFile file : Selections.of(event.getApplicationContext(), IFile.class)) {
            if (!"miron".equals(file.getFileExtension()) || file.getLocation() == null) {
                continue;
            }
            Job job = new Job("Generating MIRoN artefacts for " + file.getName()) {
                @Override
                protected IStatus run(IProgressMonitor monitor) {
                    return ArtefactGeneration.generate(file);
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
}
