package org.miron.eclipse.builder;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.IncrementalProjectBuilder;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.SubMonitor;
import org.miron.generator.standalone.Diagnostic;

/**
 * The MIRoN builder ({@code org.miron.eclipse.builder}): checks the project's model files that
 * changed and every file that imports them (through {@link ImportGraph}), replaces their markers,
 * and generates each valid .miron among them into generated/ beside it. A full build (the first
 * of a session, a clean) checks every model file of the project.
 */
public final class MironBuilder extends IncrementalProjectBuilder {
    public static final String ID = "org.miron.eclipse.builder";

    private final ImportGraph graph = new ImportGraph();

    @Override
    protected IProject[] build(int kind, Map<String, String> args, IProgressMonitor monitor) throws CoreException {
        IResourceDelta delta = kind == FULL_BUILD ? null : getDelta(getProject());
        Set<IFile> toCheck;
        if (delta == null || graph.isEmpty()) {
            graph.clear();
            getProject().deleteMarkers(ProblemMarkers.TYPE, true, IResource.DEPTH_INFINITE);
            toCheck = new LinkedHashSet<>(ModelFiles.of(getProject()));
        } else {
            toCheck = changedFiles(delta);
        }
        check(toCheck, SubMonitor.convert(monitor, "Checking MIRoN models", toCheck.size()));
        return null;
    }

    @Override
    protected void clean(IProgressMonitor monitor) throws CoreException {
        graph.clear();
        getProject().deleteMarkers(ProblemMarkers.TYPE, true, IResource.DEPTH_INFINITE);
    }

    /** The model files added or changed, and every file importing one that changed or went. */
    private Set<IFile> changedFiles(IResourceDelta delta) throws CoreException {
        Set<IFile> changed = new LinkedHashSet<>();
        Set<IFile> touched = new LinkedHashSet<>();
        delta.accept(d -> {
            IResource resource = d.getResource();
            if (resource.getType() == IResource.FILE && hasModelExtension(resource)) {
                IFile file = (IFile) resource;
                touched.add(file);
                if (d.getKind() == IResourceDelta.REMOVED) {
                    graph.remove(file);
                } else if (ModelFiles.isModel(file)) {
                    changed.add(file);
                }
            }
            return !resource.isDerived();
        });
        changed.addAll(graph.importersOf(touched));
        return changed;
    }

    private static boolean hasModelExtension(IResource resource) {
        String extension = resource.getFileExtension();
        return extension != null && Set.of("bt", "xml", "roqme", "miron").contains(extension);
    }

    private void check(Set<IFile> files, SubMonitor monitor) throws CoreException {
        // Diagnostics by file, over every check: a file imported by several is marked once.
        Map<IFile, Set<Diagnostic>> byFile = new HashMap<>();
        List<ModelCheck> checks = new ArrayList<>();
        for (IFile file : files) {
            if (monitor.isCanceled()) {
                return;
            }
            monitor.subTask(file.getName());
            ModelCheck check = ModelCheck.of(file);
            graph.put(file, check.loaded());
            for (IFile loaded : check.loaded()) {
                if (loaded.getProject().equals(getProject())) {
                    byFile.computeIfAbsent(loaded, f -> new TreeSet<>());
                }
            }
            for (Diagnostic d : check.diagnostics()) {
                IFile marked = ModelFiles.fromPath(d.file());
                if (marked != null && byFile.containsKey(marked)) {
                    byFile.get(marked).add(d);
                }
            }
            checks.add(check);
            monitor.worked(1);
        }
        for (Map.Entry<IFile, Set<Diagnostic>> entry : byFile.entrySet()) {
            ProblemMarkers.replace(entry.getKey(), entry.getValue());
        }
        for (ModelCheck check : checks) {
            if ("miron".equals(check.root().getFileExtension()) && check.valid()) {
                IStatus status = ArtefactGeneration.generate(check.root());
                if (!status.isOK()) {
                    // A generator's own error (the model validated): on the model, like a check's.
                    ProblemMarkers.add(check.root(), status.getMessage());
                }
            }
        }
    }
}
