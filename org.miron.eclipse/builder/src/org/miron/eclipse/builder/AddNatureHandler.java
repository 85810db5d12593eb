package org.miron.eclipse.builder;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;

/** "Configure > Add MIRoN Nature" on the selected projects: the nature, hence the builder. */
public final class AddNatureHandler extends AbstractHandler {
    @Override
    public Object execute(ExecutionEvent event) throws ExecutionException {
        for (IResource resource : Selections.of(event.getApplicationContext(), IResource.class)) {
            IProject project = resource.getProject();
            try {
                if (project != null && project.isOpen()) {
                    MironNature.addTo(project);
                }
            } catch (CoreException e) {
                throw new ExecutionException("Cannot add the MIRoN nature to " + project.getName(), e);
            }
        }
        return null;
    }
}
