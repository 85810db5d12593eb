package org.miron.cli;

import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;
import java.io.File;
import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;

import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.formatting2.BtFormatting;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** `miron format FILE`: prints the file formatted by its language's Xtext formatter. */
@Command(name = "format", mixinStandardHelpOptions = true,
        description = "Prints a model file formatted: indented XML for behaviour trees, one declaration per line and "
                + "indented blocks for RoQME and MIRoN; comments kept.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:formatted", "1:the file has syntax errors", "2:usage error" })
public class FormatCommand implements Callable<Integer> {

    @Parameters(arity = "1", paramLabel = "FILE", description = "The file to format.")
    File file;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        Integer usage = Files.checkReadable(List.of(file), spec);
        if (usage != null) {
            return usage;
        }
        ModelLoader loader = new ModelLoader();
        XtextResource resource = (XtextResource) loader.load(file);
        if (!resource.getParseResult().getSyntaxErrors().iterator().hasNext()) {
            PrintWriter out = spec.commandLine().getOut();
            out.print(BtFormatting.format(resource));
            out.flush();
            return 0;
        }
        // Formatting a file that does not parse would lose text: report instead.
        PrintWriter err = spec.commandLine().getErr();
        loader.validateAll().stream().filter(d -> d.severity() == Diagnostic.Severity.ERROR)
                .forEach(err::println);
        err.flush();
        return 1;
    }
}
