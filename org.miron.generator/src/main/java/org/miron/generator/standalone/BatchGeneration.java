package org.miron.generator.standalone;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.IFileSystemAccess;
import org.eclipse.xtext.generator.IFileSystemAccess2;
import org.eclipse.xtext.generator.JavaIoFileSystemAccess;
import org.eclipse.xtext.generator.OutputConfiguration;
import org.eclipse.xtext.resource.impl.ResourceServiceProviderRegistryImpl;
import org.eclipse.xtext.util.RuntimeIOException;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.generator.GenerationError;
import org.miron.generator.MironGenerator;
import org.miron.generator.StagedGeneration;
import org.miron.generator.WeightPolicy;

/**
 * Generates several MIRoN (and RoQME) models loaded by a {@link ModelLoader} all or nothing: the models and
 * everything they import are validated, every model is generated in memory, and only when none
 * failed (and no two write the same file) is anything written to the target. The command line,
 * the Gradle plugin (org.miron.gradle), the repository's `gradle generate` and the language server
 * run generation through this class.
 */
public final class BatchGeneration {

    /** How far a run got. */
    public enum Stage {
        /** validation found errors: nothing generated */
        INVALID,
        /** a generator reported errors: nothing written */
        GENERATION_FAILED,
        /** the target could not be written to */
        WRITE_FAILED,
        /** every file written */
        WRITTEN
    }

    /**
     * What a run did: the validation diagnostics (warnings included), the generators' errors, the
     * files written (relative to the target's output folder) and, when writing failed, why.
     */
    public record Outcome(Stage stage, List<Diagnostic> validation, List<Diagnostic> generationErrors,
            List<String> written, String writeError) {

        public boolean succeeded() {
            return stage == Stage.WRITTEN;
        }
    }

    private final ModelLoader loader;
    private final MironGenerator generator = new MironGenerator();

    public BatchGeneration(ModelLoader loader, WeightPolicy weights) {
        this(loader, weights, null);
    }

    /**
     * btFormat: the BehaviorTree.CPP format of the woven trees, 3 or 4; null writes each in the
     * format of the tree its model imports.
     */
    public BatchGeneration(ModelLoader loader, WeightPolicy weights, Integer btFormat) {
        if (btFormat != null && btFormat != 3 && btFormat != 4) {
            throw new IllegalArgumentException("BehaviorTree.CPP format " + btFormat + " (3 or 4)");
        }
        this.loader = loader;
        generator.setWeights(weights);
        generator.setBtFormat(btFormat);
    }

    /**
     * What `miron generate -o dir` does: loads the model files (which must exist) with everything
     * they import, then generates the MIRoN and RoQME models among them into dir, all or nothing.
     */
    public Outcome generate(List<File> models, Path dir) {
        List<Resource> resources = new ArrayList<>();
        models.forEach(f -> resources.add(loader.load(f)));
        return run(resources, folder(dir));
    }

    /** Generates the MIRoN and RoQME models among resources (loaded by this run's loader) into target. */
    public Outcome run(List<Resource> resources, IFileSystemAccess2 target) {
        // Not the expensive rule check (miron check's): generation of large models keeps its speed.
        List<Diagnostic> validation = loader.validateAll(org.eclipse.xtext.validation.CheckMode.NORMAL_AND_FAST);
        if (validation.stream().anyMatch(d -> d.severity() == Diagnostic.Severity.ERROR)) {
            return new Outcome(Stage.INVALID, validation, List.of(), List.of(), null);
        }
        List<StagedGeneration> generated = new ArrayList<>();
        List<Diagnostic> errors = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (Resource resource : resources) {
            if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof RoqmeModel)) {
                continue;
            }
            StagedGeneration result;
            try {
                result = generator.stage(resource, target);
            } catch (RuntimeException e) {
                // A generator bug must still end in a clear message, never a stack trace.
                errors.add(fileError(resource, "internal error of the generator, please report it: " + e));
                continue;
            }
            for (GenerationError e : result.errors()) {
                errors.add(loader.error(e.source(), e.code(), e.message()));
            }
            for (String name : result.files().names()) {
                if (!names.add(name)) {
                    errors.add(fileError(resource,
                            "another model also generates " + name + ": generate them into different folders"));
                }
            }
            generated.add(result);
        }
        if (!errors.isEmpty()) {
            return new Outcome(Stage.GENERATION_FAILED, validation, errors.stream().distinct().sorted().toList(),
                    List.of(), null);
        }
        // Every model generated: only now is anything written.
        List<String> written = new ArrayList<>();
        try {
            for (StagedGeneration result : generated) {
                result.files().flushTo(target);
                written.addAll(result.files().names());
            }
        } catch (RuntimeIOException e) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            return new Outcome(Stage.WRITE_FAILED, validation, List.of(), written, cause.getMessage());
        }
        return new Outcome(Stage.WRITTEN, validation, List.of(), written, null);
    }

    private Diagnostic fileError(Resource resource, String message) {
        return new Diagnostic(loader.displayPath(resource.getURI()), 0, 0, Diagnostic.Severity.ERROR, message);
    }

    /** Files under dir, created when missing, overwritten, in UTF-8 whatever the platform's default. */
    public static JavaIoFileSystemAccess folder(Path dir) {
        OutputConfiguration config = new OutputConfiguration(IFileSystemAccess.DEFAULT_OUTPUT);
        config.setOutputDirectory(dir.toAbsolutePath().normalize().toString());
        config.setCreateOutputDirectory(true);
        config.setOverrideExistingResources(true);
        JavaIoFileSystemAccess fsa = new JavaIoFileSystemAccess(new ResourceServiceProviderRegistryImpl(),
                uri -> StandardCharsets.UTF_8.name());
        fsa.setOutputConfigurations(Map.of(IFileSystemAccess.DEFAULT_OUTPUT, config));
        fsa.setWriteTrace(false);
        return fsa;
    }
}
