package org.miron.cli.run;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.miron.generator.RoqmeRuntimeModel;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.ModelReader;

/**
 * What {@code miron run} needs of a {@code .miron}: its generation (validated with everything it
 * imports, as {@code miron generate} does), from the {@link GeneratedCache} when the model and
 * all it imports are unchanged since the last run, otherwise generated anew in a JVM of its own
 * ({@link GenerationProcess}); the engine's io.json there, the RoQME part compiled (null when the
 * model has none or the provider is not wanted), the requirements (null when it states none).
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
    private final String origin;
    private final boolean temporary;

    private RunModel(Path dir, String name, CompiledModel roqme, RequirementModel requirements, String origin, boolean temporary) {
        this.dir = dir;
        this.name = name;
        this.roqme = roqme;
        this.requirements = requirements;
        this.origin = origin;
        this.temporary = temporary;
    }

    /** {@code $XDG_CACHE_HOME/miron/run}, or {@code ~/.cache/miron/run}. */
    public static Path defaultCache() {
        return GeneratedCache.defaultRoot();
    }

    /**
     * The model's generation; errors are printed to err as {@code file:line:col: error [code]: message}.
     *
     * @param params    the RoQME params' overrides; null: the provider is not wanted (its part is not compiled)
     * @param cacheRoot where generations are kept between runs; when it cannot be written, a
     *                  temporary folder is used (and deleted on close)
     */
    public static RunModel generate(Path model, Map<String, String> params, PrintWriter err, Path cacheRoot) throws Refused {
        if (!Files.isReadable(model) || !model.getFileName().toString().endsWith(".miron")) {
            throw new Refused(2, model + ": error: " + (Files.isReadable(model) ? "miron run needs a .miron model" : "cannot read the file"));
        }
        String name = model.getFileName().toString().replaceFirst("\\.miron$", "");
        GeneratedCache cache = new GeneratedCache(cacheRoot);
        Path dir = cache.lookup(model).orElse(null);
        String origin = dir == null ? null : "unchanged since it was generated into " + dir;
        boolean temporary = false;
        if (dir == null) {
            long t0 = System.nanoTime();
            Path staged;
            try {
                staged = cache.staging();
            } catch (IOException e) {
                temporary = true;
                try {
                    staged = Files.createTempDirectory("miron-run-");
                } catch (IOException e2) {
                    throw new Refused(2, "miron run: error: cannot create a folder to generate into: " + e2.getMessage());
                }
            }
            generateInto(model, staged, err);
            dir = staged;
            if (!temporary) {
                try {
                    dir = cache.store(model, staged, read(staged));
                } catch (IOException e) {
                    temporary = true; // runs all the same, from the staging folder
                }
            }
            origin = String.format(java.util.Locale.ROOT, "generated in %.1f s into %s", (System.nanoTime() - t0) / 1e9, dir);
        }
        try {
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
            return new RunModel(dir, name, roqme, requirements, origin, temporary);
        } catch (ModelException e) {
            if (temporary) {
                GeneratedCache.delete(dir);
            }
            throw new Refused(1, e.getMessage());
        } catch (RuntimeException e) {
            if (temporary) {
                GeneratedCache.delete(dir);
            }
            throw new Refused(2, "miron run: error: " + e.getMessage());
        }
    }

    /** {@code miron generate} into dir in a JVM of its own; the diagnostics go to err. */
    private static void generateInto(Path model, Path dir, PrintWriter err) throws Refused {
        int status;
        try {
            status = GenerationProcess.run(model, dir, dir.resolve(INPUTS), err);
        } catch (IOException e) {
            GeneratedCache.delete(dir);
            throw new Refused(2, "miron run: error: cannot start the generation: " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            GeneratedCache.delete(dir);
            throw new Refused(2, "miron run: error: interrupted while generating");
        }
        if (status != 0) {
            GeneratedCache.delete(dir);
            throw new Refused(status == 1 ? 1 : 2, model + ": the model has errors: nothing runs");
        }
    }

    private static final String INPUTS = "inputs.list";

    /** The files the generation read, as miron generate --inputs listed them. */
    private static List<Path> read(Path dir) throws IOException {
        return Files.readAllLines(dir.resolve(INPUTS)).stream().filter(l -> !l.isBlank()).map(Path::of).toList();
    }

    /** Where the model comes from this time: the cache, or generated now (for the start-up lines). */
    public String origin() {
        return origin;
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

    /** Deletes the generation if it was not kept in the cache. */
    @Override
    public void close() {
        if (temporary) {
            GeneratedCache.delete(dir);
        }
    }
}
