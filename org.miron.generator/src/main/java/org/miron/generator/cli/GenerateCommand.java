package org.miron.generator.cli;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.dsl.miron.MironModel;
import org.miron.generator.GenerationError;
import org.miron.generator.MironGenerator;
import org.miron.generator.WeightPolicy;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * `miron generate FILE.miron... [-o DIR] [--weights need|metric]`: validates the models and
 * everything they import, then writes name.ext.xml, name.mzn, name.dzn and name.io.json per model.
 * Any error (validation or generation) is printed and nothing at all is written.
 */
@Command(name = "generate", mixinStandardHelpOptions = true,
        description = "Generates the woven behaviour tree (name.ext.xml), the MiniZinc model (name.mzn, name.dzn) "
                + "and the engine's input/output map (name.io.json) of MIRoN models.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:generated", "1:model errors (listed; nothing written)", "2:usage error" })
public class GenerateCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "FILE.miron", description = "MIRoN models to generate.")
    List<File> files;

    @Option(names = { "-o", "--output" }, paramLabel = "DIR", defaultValue = ".",
            description = "Output folder (default: the current folder); created when missing.")
    File output;

    @Option(names = "--weights", paramLabel = "need|metric", defaultValue = "need",
            description = "Objective weights: need (default, weight = 1 - metric: the least fulfilled property "
                    + "matters most) or metric (weight = metric, as the original MIRoN tools).")
    String weights;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        WeightPolicy policy = WeightPolicy.of(weights);
        if (policy == null) {
            throw new ParameterException(spec.commandLine(),
                    "--weights must be need or metric, not '" + weights + "'");
        }
        Integer usage = Files.checkReadable(files, spec);
        if (usage != null) {
            return usage;
        }
        PrintWriter err = spec.commandLine().getErr();
        for (File file : files) {
            if (!file.getName().endsWith(".miron")) {
                err.println(file + ": error: generate needs .miron models");
                err.flush();
                return Files.USAGE;
            }
        }
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>();
        files.forEach(f -> resources.add(loader.load(f)));
        List<Diagnostic> diagnostics = loader.validateAll();
        PrintWriter out = spec.commandLine().getOut();
        diagnostics.forEach(out::println);
        out.flush();
        if (diagnostics.stream().anyMatch(d -> d.severity() == Diagnostic.Severity.ERROR)) {
            return 1;
        }

        Path dir = output.toPath();
        Map<Path, String> outputs = new LinkedHashMap<>();
        List<Diagnostic> errors = new ArrayList<>();
        for (Resource resource : resources) {
            if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof MironModel)) {
                continue;
            }
            MironGenerator.Result result;
            try {
                result = new MironGenerator(policy, dir).generate((MironModel) resource.getContents().get(0));
            } catch (RuntimeException e) {
                // A generator bug must still end in a clear message, never a stack trace.
                errors.add(new Diagnostic(loader.displayPath(resource.getURI()), 0, 0, Diagnostic.Severity.ERROR,
                        "internal error of the generator, please report it: " + e));
                continue;
            }
            for (GenerationError e : result.errors) {
                errors.add(loader.error(e.source(), e.message()));
            }
            for (Map.Entry<String, String> file : result.files.entrySet()) {
                if (outputs.put(dir.resolve(file.getKey()), file.getValue()) != null) {
                    errors.add(new Diagnostic(loader.displayPath(resource.getURI()), 0, 0, Diagnostic.Severity.ERROR,
                            "another model also generates " + file.getKey() + ": generate them into different folders"));
                }
            }
        }
        if (!errors.isEmpty()) {
            errors.stream().distinct().sorted().forEach(out::println);
            out.flush();
            return 1;
        }
        try {
            java.nio.file.Files.createDirectories(dir);
            for (Map.Entry<Path, String> file : outputs.entrySet()) {
                java.nio.file.Files.writeString(file.getKey(), file.getValue(), StandardCharsets.UTF_8);
                out.println("wrote " + file.getKey());
            }
        } catch (IOException e) {
            err.println(dir + ": error: cannot write: " + e.getMessage());
            err.flush();
            return 1;
        }
        out.flush();
        return 0;
    }
}
