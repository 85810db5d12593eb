package org.miron.cli;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.Callable;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.BTModel;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.convert.BtFormatConverter;
import org.miron.bt.convert.Conversion;
import org.miron.bt.convert.ConversionProblem;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** `miron convert --to 4|3 FILE [-o OUT]`: a behaviour tree in the other BehaviorTree.CPP format. */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = "Converts a behaviour tree between the XML formats of BehaviorTree.CPP 3 (no BTCPP_format) and "
                + "4 (BTCPP_format=\"4\"). Version 3 to 4 as BehaviorTree.CPP's convert_v3_to_v4.py, plus "
                + "BlackboardCheck*, SubTreePlus and Parallel ports; version 4 to 3 where BehaviorTree.CPP 3 has an "
                + "equivalent, else an error for each element without one.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:converted", "1:the file has errors or elements without equivalent", "2:usage error" })
public class ConvertCommand implements Callable<Integer> {

    @Option(names = "--to", required = true, paramLabel = "3|4", description = "The BehaviorTree.CPP format to write.")
    int to;

    @Option(names = { "-o", "--output" }, paramLabel = "OUT", description = "Write here instead of standard output.")
    File output;

    @Parameters(arity = "1", paramLabel = "FILE", description = "The behaviour tree (.bt or woven .xml).")
    File file;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        if (to != 3 && to != 4) {
            err.println("error: --to must be 3 or 4, not " + to);
            err.flush();
            return Files.USAGE;
        }
        Integer usage = Files.checkReadable(List.of(file), spec);
        if (usage != null) {
            return usage;
        }
        if (!file.getName().endsWith(".bt") && !file.getName().endsWith(".xml")) {
            err.println(file + ": error: not a behaviour tree, expected .bt or a woven .xml");
            err.flush();
            return Files.USAGE;
        }
        ModelLoader loader = new ModelLoader();
        Resource resource = loader.load(file);
        List<Diagnostic> errors = loader.validateAll().stream()
                .filter(d -> d.severity() == Diagnostic.Severity.ERROR).toList();
        if (!errors.isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            errors.forEach(err::println); // converting a broken file would only move its errors
            err.flush();
            return 1;
        }
        BtFormatConverter.ConvertedFile converted = BtFormatConverter.convertFile((XtextResource) resource, to);
        Conversion conversion = converted.conversion();
        if (!conversion.succeeded()) {
            String path = loader.displayPath(resource.getURI());
            for (ConversionProblem problem : conversion.getProblems()) {
                err.println(problem.format(path));
            }
            err.flush();
            return 1;
        }
        String text = converted.text();
        if (output == null) {
            PrintWriter out = spec.commandLine().getOut();
            out.print(text);
            out.flush();
        } else {
            java.nio.file.Files.writeString(output.toPath(), text, StandardCharsets.UTF_8);
        }
        return 0;
    }
}
