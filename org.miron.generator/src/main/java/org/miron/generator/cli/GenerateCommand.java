package org.miron.generator.cli;

import java.io.File;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.generator.IFileSystemAccess;
import org.eclipse.xtext.generator.JavaIoFileSystemAccess;
import org.eclipse.xtext.generator.OutputConfiguration;
import org.eclipse.xtext.resource.impl.ResourceServiceProviderRegistryImpl;
import org.eclipse.xtext.util.RuntimeIOException;
import org.miron.dsl.miron.MironModel;
import org.miron.generator.GenerationError;
import org.miron.generator.MironGenerator;
import org.miron.generator.StagedGeneration;
import org.miron.generator.WeightPolicy;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * `miron generate FILE.miron... [-o DIR] [--weights need|metric]`: validates the models and
 * everything they import, then writes name.ext.xml, name.mzn, name.dzn and name.io.json per model
 * with {@link MironGenerator} through a file-system access on DIR. Any error (validation or
 * generation, of any model) is printed and nothing at all is written.
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

    /** Files under dir, created when missing, overwritten, in UTF-8 whatever the platform's default. */
    private static JavaIoFileSystemAccess fileSystemAccess(Path dir) {
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
        JavaIoFileSystemAccess target = fileSystemAccess(dir);
        MironGenerator generator = new MironGenerator();
        generator.setWeights(policy);
        List<StagedGeneration> generated = new ArrayList<>();
        Set<String> names = new HashSet<>();
        List<Diagnostic> errors = new ArrayList<>();
        for (Resource resource : resources) {
            if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof MironModel)) {
                continue;
            }
            StagedGeneration result;
            try {
                result = generator.stage(resource, target);
            } catch (RuntimeException e) {
                // A generator bug must still end in a clear message, never a stack trace.
                errors.add(new Diagnostic(loader.displayPath(resource.getURI()), 0, 0, Diagnostic.Severity.ERROR,
                        "internal error of the generator, please report it: " + e));
                continue;
            }
            for (GenerationError e : result.errors()) {
                errors.add(loader.error(e.source(), e.message()));
            }
            for (String name : result.files().names()) {
                if (!names.add(name)) {
                    errors.add(new Diagnostic(loader.displayPath(resource.getURI()), 0, 0, Diagnostic.Severity.ERROR,
                            "another model also generates " + name + ": generate them into different folders"));
                }
            }
            generated.add(result);
        }
        if (!errors.isEmpty()) {
            errors.stream().distinct().sorted().forEach(out::println);
            out.flush();
            return 1;
        }
        // Every model generated: only now is anything written.
        try {
            for (StagedGeneration result : generated) {
                result.files().flushTo(target);
                result.files().names().forEach(name -> out.println("wrote " + dir.resolve(name)));
            }
        } catch (RuntimeIOException e) {
            Throwable cause = e.getCause() == null ? e : e.getCause();
            err.println(dir + ": error: cannot write: " + cause.getMessage());
            err.flush();
            return 1;
        }
        out.flush();
        return 0;
    }
}
