package org.miron.eclipse.builder;

import java.io.File;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.Path;
import org.eclipse.emf.common.util.URI;
import org.miron.bt.resource.BtXmlFiles;

/** Which workspace files are MIRoN models, and the way between them and the core's java.io files. */
final class ModelFiles {
    private ModelFiles() {
    }

    /**
     * A .bt, .roqme or .miron file, or a .xml whose root element is {@code <root>} (any other .xml is
     * not ours); never a derived file (generated/ holds woven trees the builder wrote itself).
     */
    static boolean isModel(IResource resource) {
        if (resource.getType() != IResource.FILE || resource.isDerived(IResource.CHECK_ANCESTORS)
                || resource.getLocation() == null) {
            return false;
        }
        String extension = resource.getFileExtension();
        if ("bt".equals(extension) || "roqme".equals(extension) || "miron".equals(extension)) {
            return true;
        }
        return "xml".equals(extension) && resource.exists()
                && BtXmlFiles.looksLikeBehaviourTree(URI.createFileURI(resource.getLocation().toOSString()));
    }

    /** Every model file of a project. */
    static List<IFile> of(IProject project) throws CoreException {
        List<IFile> files = new ArrayList<>();
        project.accept(resource -> {
            if (resource.isDerived()) {
                return false;
            }
            if (isModel(resource)) {
                files.add((IFile) resource);
            }
            return true;
        });
        return files;
    }

    static File toFile(IFile file) {
        return file.getLocation().toFile();
    }

    /** The workspace file of a path the core gives (absolute, or relative to the working directory). */
    static IFile fromPath(String path) {
        File file = new File(path).getAbsoluteFile();
        IPath location = Path.fromOSString(file.getPath());
        return ResourcesPlugin.getWorkspace().getRoot().getFileForLocation(location);
    }
}
