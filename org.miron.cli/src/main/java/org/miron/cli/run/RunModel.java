package org.miron.cli.run;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.miron.generator.RoqmeRuntimeModel;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;

/**
 * What {@code miron run} needs of a {@code .miron}: generated (validated with everything it imports,
 * as {@code miron generate} does) into a temporary folder that {@link #close} deletes; the engine's
 * io.json there, the RoQME part compiled (null when the model has none or the provider is not
 * wanted), the requirements (null when it states none).
 */
public final class RunModel implements AutoCloseable {
    /** A model that cannot run: its reasons are printed, {@code status} is the exit status (1 model errors, 2 other). */
    public static final class Refused extends Exception {
        private final int status;

        Refused(int status, String message) {
            super(message);
            this.status = status;
        }

        public int status() {
            return status;
        }
    }

    private final Path dir;
    private final String name;
    private final CompiledModel roqme;
    private final RequirementModel requirements;

    private RunModel(Path dir, String name, CompiledModel roqme, RequirementModel requirements) {
        this.dir = dir;
        this.name = name;
        this.roqme = roqme;
        this.requirements = requirements;
    }

    /**
     * Generates model; errors are printed to err as {@code file:line:col: error [code]: message}.
     *
     * @param params the RoQME params' overrides; null: the provider is not wanted (its part is not compiled)
     */
    public static RunModel generate(Path model, Map<String, String> params, PrintWriter err) throws Refused {
        if (!Files.isReadable(model) || !model.getFileName().toString().endsWith(".miron")) {
            throw new Refused(2, model + ": error: " + (Files.isReadable(model) ? "miron run needs a .miron model" : "cannot read the file"));
        }
        Path dir;
        try {
            dir = Files.createTempDirectory("miron-run-");
        } catch (IOException e) {
            throw new Refused(2, "miron run: error: cannot create a temporary folder: " + e.getMessage());
        }
        String name = model.getFileName().toString().replaceFirst("\\.miron$", "");
        try {
            BatchGeneration.Outcome outcome = new BatchGeneration(new ModelLoader(), WeightPolicy.NEED, null)
                    .generate(List.of(model.toFile()), dir);
            if (!outcome.succeeded()) {
                outcome.validation().forEach(err::println);
                outcome.generationErrors().forEach(err::println);
                if (outcome.stage() == BatchGeneration.Stage.WRITE_FAILED) {
                    throw new Refused(2, dir + ": error: cannot write: " + outcome.writeError());
                }
                throw new Refused(1, model + ": the model has errors: nothing runs");
            }
            CompiledModel roqme = null;
            Path roqmeJson = dir.resolve(name + RoqmeRuntimeModel.SUFFIX);
            if (params != null && Files.isRegularFile(roqmeJson)) {
                roqme = Compiler.compile(ModelReader.read(roqmeJson), params);
            }
            Path requirementsJson = dir.resolve(name + ".requirements.json");
            RequirementModel requirements = null;
            if (Files.isRegularFile(requirementsJson)) {
                requirements = RequirementModel.load(requirementsJson);
                if (requirements.requirements().isEmpty()) {
                    requirements = null;
                }
            }
            return new RunModel(dir, name, roqme, requirements);
        } catch (ModelException e) {
            delete(dir);
            throw new Refused(1, e.getMessage());
        } catch (Refused | RuntimeException e) {
            delete(dir);
            if (e instanceof Refused r) {
                throw r;
            }
            throw new Refused(2, "miron run: error: " + e.getMessage());
        }
    }

    /** The generated engine input/output map. */
    public Path ioJson() {
        return dir.resolve(name + ".io.json");
    }

    /** The compiled RoQME part, or null. */
    public CompiledModel roqme() {
        return roqme;
    }

    /** The requirements, or null. */
    public RequirementModel requirements() {
        return requirements;
    }

    @Override
    public void close() {
        delete(dir);
    }

    private static void delete(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // a temporary folder left behind
        }
    }
}
