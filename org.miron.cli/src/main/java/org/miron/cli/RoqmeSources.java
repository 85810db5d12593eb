package org.miron.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.RoqmeRuntimeModel;
import org.miron.generator.StagedFiles;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * The provider's model from what a user has at hand: a generated {@code name.roqme.json}, or a
 * {@code .roqme} / {@code .miron} source generated in memory (validated with everything it imports,
 * as {@code miron generate} does, nothing written). Problems are printed as {@code file:line:col:
 * error [code]: message}.
 */
public final class RoqmeSources {
    private RoqmeSources() {
    }

    /** Whether the file is a model source this class generates (rather than a runtime model). */
    public static boolean isSource(Path file) {
        String name = String.valueOf(file.getFileName());
        return name.endsWith(".roqme") || name.endsWith(".miron");
    }

    /** The runtime model of file, or null after printing why not to err. */
    public static RoqmeModel read(Path file, PrintWriter err) {
        try {
            if (!isSource(file)) {
                return ModelReader.read(file);
            }
            if (!Files.isReadable(file)) {
                err.println(file + ": error: cannot read the file");
                return null;
            }
            ModelLoader loader = new ModelLoader();
            Resource resource = loader.load(file.toFile());
            StagedFiles target = new StagedFiles();
            BatchGeneration.Outcome outcome = new BatchGeneration(loader, WeightPolicy.NEED).run(List.of(resource), target);
            if (!outcome.succeeded()) {
                outcome.validation().stream().filter(d -> d.severity() == Diagnostic.Severity.ERROR).forEach(err::println);
                outcome.generationErrors().forEach(err::println);
                return null;
            }
            String name = file.getFileName().toString().replaceFirst("\\.(roqme|miron)$", "") + RoqmeRuntimeModel.SUFFIX;
            String text = target.text(name);
            if (text == null) {
                err.println(file + ": error: the model has no RoQME part");
                return null;
            }
            return ModelReader.parse(name, text);
        } catch (ModelException e) {
            err.println(e.getMessage());
            return null;
        }
    }

    /** The compiled runtime model of file with the given params, or null after printing why not. */
    public static CompiledModel compile(Path file, Map<String, String> params, PrintWriter err) {
        RoqmeModel model = read(file, err);
        if (model == null) {
            return null;
        }
        try {
            return Compiler.compile(model, params);
        } catch (ModelException e) {
            err.println(e.getMessage());
            return null;
        }
    }
}
