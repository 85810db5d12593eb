package org.miron.cli;

import java.io.File;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * `miron generate FILE.miron|FILE.roqme... [-o DIR] [--weights need|metric] [--bt-format 3|4]`: validates the
 * models and everything they import, then writes name.ext.xml, name.mzn, name.dzn, name.io.json and
 * name.roqme.json per MIRoN model, and name.roqme.json per RoQME model, with MironGenerator through a
 * file-system access on DIR. Any error (validation or generation, of any model) is printed and nothing
 * at all is written.
 */
@Command(name = "generate", mixinStandardHelpOptions = true,
        description = "Generates the woven behaviour tree (name.ext.xml), the MiniZinc model (name.mzn, name.dzn), "
                + "the engine's input/output map (name.io.json) and the RoQME runtime model (name.roqme.json) of MIRoN "
                + "models, and the RoQME runtime model of RoQME models.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:generated", "1:model errors (listed; nothing written)", "2:usage error" })
public class GenerateCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "FILE.miron|FILE.roqme", description = "MIRoN and RoQME models to generate.")
    List<File> files;

    @Option(names = { "-o", "--output" }, paramLabel = "DIR", defaultValue = ".",
            description = "Output folder (default: the current folder); created when missing.")
    File output;

    @Option(names = "--weights", paramLabel = "need|metric", defaultValue = "need",
            description = "Objective weights: need (default, weight = 1 - metric: the least fulfilled property "
                    + "matters most) or metric (weight = metric, as the original MIRoN tools).")
    String weights;

    @Option(names = "--bt-format", paramLabel = "3|4",
            description = "BehaviorTree.CPP format of the woven tree: 3 or 4 (default: the format of the tree the "
                    + "model imports).")
    Integer btFormat;

    @Option(names = "--inputs", paramLabel = "FILE",
            description = "Also write every file the generation read (the models and all they import), one absolute "
                    + "path a line: what a build tool or miron run's cache checks for changes.")
    File inputs;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        WeightPolicy policy = WeightPolicy.of(weights);
        if (policy == null) {
            throw new ParameterException(spec.commandLine(),
                    "--weights must be need or metric, not '" + weights + "'");
        }
        if (btFormat != null && btFormat != 3 && btFormat != 4) {
            throw new ParameterException(spec.commandLine(), "--bt-format must be 3 or 4, not " + btFormat);
        }
        Integer usage = Files.checkReadable(files, spec);
        if (usage != null) {
            return usage;
        }
        PrintWriter err = spec.commandLine().getErr();
        for (File file : files) {
            if (!file.getName().endsWith(".miron") && !file.getName().endsWith(".roqme")) {
                err.println(file + ": error: generate needs .miron or .roqme models");
                err.flush();
                return Files.USAGE;
            }
        }
        Path dir = output.toPath();
        ModelLoader loader = new ModelLoader();
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, policy, btFormat).generate(files, dir);
        PrintWriter out = spec.commandLine().getOut();
        outcome.validation().forEach(out::println);
        outcome.generationErrors().forEach(out::println);
        outcome.written().forEach(name -> out.println("wrote " + dir.resolve(name)));
        out.flush();
        if (outcome.stage() == BatchGeneration.Stage.WRITE_FAILED) {
            err.println(dir + ": error: cannot write: " + outcome.writeError());
            err.flush();
        }
        if (inputs != null && !writeInputs(loader, err)) {
            return 1;
        }
        return outcome.succeeded() ? 0 : 1;
    }

    private boolean writeInputs(ModelLoader loader, PrintWriter err) {
        try {
            java.nio.file.Files.write(inputs.toPath(), loader.loadedFiles().stream()
                    .map(f -> f.toPath().toAbsolutePath().normalize().toString()).distinct().toList());
            return true;
        } catch (java.io.IOException e) {
            err.println(inputs + ": error: cannot write: " + e.getMessage());
            err.flush();
            return false;
        }
    }
}
