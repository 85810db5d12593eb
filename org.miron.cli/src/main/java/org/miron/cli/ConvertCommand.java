package org.miron.cli;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.BTModel;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.formats.BtFormatConverter;
import org.miron.bt.formats.Conversion;
import org.miron.bt.formats.ConversionProblem;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * `miron convert --to 4|3 FILE [-o OUT]` or `miron convert --to 4|3 --in-place FILE...`: behaviour
 * trees in the other BehaviorTree.CPP format, comments and layout kept. All or nothing: when one
 * file has errors or elements without equivalent, no file is written.
 */
@Command(name = "convert", mixinStandardHelpOptions = true,
        description = "Converts behaviour trees between the XML formats of BehaviorTree.CPP 3 (no BTCPP_format) and "
                + "4 (BTCPP_format=\"4\"). Version 3 to 4 as BehaviorTree.CPP's convert_v3_to_v4.py, plus "
                + "BlackboardCheck*, SubTreePlus and Parallel ports; version 4 to 3 where BehaviorTree.CPP 3 has an "
                + "equivalent, else an error for each element without one. Only what changes is rewritten: comments "
                + "and layout stay. With several files, or --in-place, each file is rewritten, and none is when one "
                + "of them cannot be converted.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:converted", "1:a file has errors or elements without equivalent (nothing written)",
                "2:usage error" })
public class ConvertCommand implements Callable<Integer> {

    @Option(names = "--to", required = true, paramLabel = "3|4", description = "The BehaviorTree.CPP format to write.")
    int to;

    @Option(names = { "-o", "--output" }, paramLabel = "OUT", description = "Write here instead of standard output (one FILE).")
    File output;

    @Option(names = { "-i", "--in-place" }, description = "Rewrite each FILE with its conversion.")
    boolean inPlace;

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "The behaviour trees (.bt or BehaviorTree.CPP .xml).")
    List<File> files;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        String usageError = to != 3 && to != 4 ? "--to must be 3 or 4, not " + to
                : output != null && inPlace ? "-o and --in-place exclude each other"
                : files.size() > 1 && !inPlace ? "several files are converted --in-place (or one at a time with -o)"
                : null;
        if (usageError != null) {
            err.println("error: " + usageError);
            err.flush();
            return Files.USAGE;
        }
        Integer usage = Files.checkReadable(files, spec);
        if (usage != null) {
            return usage;
        }
        for (File file : files) {
            if (!file.getName().endsWith(".bt") && !file.getName().endsWith(".xml")) {
                err.println(file + ": error: not a behaviour tree, expected .bt or a woven .xml");
                err.flush();
                return Files.USAGE;
            }
        }
        Map<File, String> texts = new LinkedHashMap<>();
        boolean failed = false;
        for (File file : files) {
            String text = convert(file, err); // each file in its own resource set: conversions edit models in place
            failed |= text == null;
            texts.put(file, text);
        }
        err.flush();
        if (failed) {
            return 1;
        }
        if (inPlace) {
            for (Map.Entry<File, String> e : texts.entrySet()) {
                if (!e.getValue().equals(java.nio.file.Files.readString(e.getKey().toPath(), StandardCharsets.UTF_8))) {
                    java.nio.file.Files.writeString(e.getKey().toPath(), e.getValue(), StandardCharsets.UTF_8);
                    err.println("wrote " + e.getKey());
                }
            }
            err.flush();
        } else if (output == null) {
            PrintWriter out = spec.commandLine().getOut();
            out.print(texts.get(files.get(0)));
            out.flush();
        } else {
            java.nio.file.Files.writeString(output.toPath(), texts.get(files.get(0)), StandardCharsets.UTF_8);
        }
        return 0;
    }

    /** The converted text of one file, or null after printing why it cannot be converted. */
    private String convert(File file, PrintWriter err) {
        ModelLoader loader = new ModelLoader();
        Resource resource = loader.load(file);
        List<Diagnostic> errors = loader.validateAll().stream()
                .filter(d -> d.severity() == Diagnostic.Severity.ERROR).toList();
        if (!errors.isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            errors.forEach(err::println); // converting a broken file would only move its errors
            return null;
        }
        BtFormatConverter.ConvertedFile converted = BtFormatConverter.convertFile((XtextResource) resource, to);
        Conversion conversion = converted.conversion();
        if (!conversion.succeeded()) {
            String path = loader.displayPath(resource.getURI());
            for (ConversionProblem problem : conversion.getProblems()) {
                err.println(problem.format(path));
            }
            return null;
        }
        return converted.text();
    }
}
