package org.miron.generator;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;
import org.miron.testkit.Folders;
import org.miron.testkit.RepositoryRoot;

/**
 * Generates and checks models through the library the command line uses (ModelLoader,
 * BatchGeneration) and keeps the diagnostics as text, one per line.
 */
final class Toolchain {
    static final Path ROOT = RepositoryRoot.path();

    private final StringBuilder messages = new StringBuilder();

    /** Generates a model into a folder: 0 when every file was written, 1 otherwise. */
    int generate(String model, String outDir) {
        return generate(model, outDir, WeightPolicy.NEED);
    }

    /** Generates a model into a folder with the given objective weights. */
    int generate(String model, String outDir, WeightPolicy weights) {
        return generate(model, outDir, weights, null);
    }

    /** Generates a model with its woven tree in a BehaviorTree.CPP format (null: the imported tree's). */
    int generate(String model, String outDir, WeightPolicy weights, Integer btFormat) {
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>(List.of(loader.load(new File(model))));
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, weights, btFormat)
                .run(resources, BatchGeneration.folder(Path.of(outDir)));
        outcome.validation().forEach(this::add);
        outcome.generationErrors().forEach(this::add);
        if (outcome.writeError() != null) {
            messages.append("cannot write: ").append(outcome.writeError()).append('\n');
        }
        return outcome.succeeded() ? 0 : 1;
    }

    /** Validates a file and what it imports: 0 without errors, 1 with. */
    int check(String file) {
        ModelLoader loader = new ModelLoader();
        loader.load(new File(file));
        List<Diagnostic> diagnostics = loader.validateAll();
        diagnostics.forEach(this::add);
        return diagnostics.stream().anyMatch(d -> d.severity() == Diagnostic.Severity.ERROR) ? 1 : 0;
    }

    private void add(Diagnostic diagnostic) {
        messages.append(diagnostic).append('\n');
    }

    String messages() {
        return messages.toString();
    }

    /** The examples' models (examples/NAME/*.miron), sorted. */
    static List<Path> exampleModels() throws IOException {
        try (Stream<Path> files = Files.walk(ROOT.resolve("examples"), 2)) {
            return files.filter(f -> f.toString().endsWith(".miron")).sorted().collect(Collectors.toList());
        }
    }

    /** The examples' models, then those of src/test/resources/weaving (copied into dir), each sorted. */
    static List<Path> exampleAndWeavingModels(Path dir) throws IOException {
        List<Path> models = new ArrayList<>(exampleModels());
        try (Stream<Path> files = Files.list(copyResources("weaving", dir))) {
            files.filter(f -> f.toString().endsWith(".miron")).sorted().forEach(models::add);
        }
        return models;
    }

    /** Copies a folder of test resources (src/test/resources/NAME) to dir. */
    static Path copyResources(String name, Path dir) {
        return Folders.copy(ROOT.resolve("org.miron.generator/src/test/resources").resolve(name), dir);
    }
}
