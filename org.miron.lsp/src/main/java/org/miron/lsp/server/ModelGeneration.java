package org.miron.lsp.server;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.JavaIoFileSystemAccess;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.RuntimeIOException;
import org.miron.generator.GenerationError;
import org.miron.generator.MironGenerator;
import org.miron.generator.StagedGeneration;
import org.miron.generator.standalone.BatchGeneration;

/** Runs the MIRoN generator on a resource into a folder: all files, or none when there is an error. */
final class ModelGeneration {

    record Result(List<String> written, List<String> errors) {
    }

    private ModelGeneration() {
    }

    static Result run(Resource resource, Path folder) {
        JavaIoFileSystemAccess target = BatchGeneration.folder(folder);
        StagedGeneration staged;
        try {
            staged = new MironGenerator().stage(resource, target);
        } catch (RuntimeException e) {
            // A generator bug must still end in a clear answer, never a dead request.
            return new Result(List.of(), List.of("internal error of the generator, please report it: " + e));
        }
        if (!staged.succeeded()) {
            List<String> errors = new ArrayList<>();
            for (GenerationError error : staged.errors()) {
                errors.add(position(error) + (error.code() == null ? "" : "[" + error.code() + "] ") + error.message());
            }
            return new Result(List.of(), errors);
        }
        try {
            staged.files().flushTo(target);
        } catch (RuntimeIOException e) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            return new Result(List.of(), List.of("cannot write into " + folder + ": " + cause.getMessage()));
        }
        return new Result(staged.files().names().stream().map(name -> folder.resolve(name).toString()).toList(),
                List.of());
    }

    private static String position(GenerationError error) {
        ICompositeNode node = error.source() == null ? null : NodeModelUtils.findActualNodeFor(error.source());
        if (node == null || error.source().eResource() == null) {
            return "";
        }
        return error.source().eResource().getURI().lastSegment() + ":" + node.getStartLine() + ": ";
    }

}
