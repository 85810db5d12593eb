package org.miron.cli;

import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;
import java.io.File;
import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** `miron check FILE...`: validates models and everything they import. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = { "Checks model files (and the files they import); prints file:line:col: error [code]: message"
                + " (or warning [code]:), or with --format json one JSON object per line: file, line, column,"
                + " endLine, endColumn, severity, code, message and data.",
                "Codes are listed in docs/issue-codes.md." },
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:all files valid", "1:errors found", "2:usage error" })
public class CheckCommand implements Callable<Integer> {

    /** How diagnostics are printed. */
    enum Format {
        text, json
    }

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "Model files to check.")
    List<File> files;

    @Option(names = "--format", paramLabel = "FORMAT", defaultValue = "text",
            description = "text (file:line:col: severity [code]: message) or json (JSON Lines);"
                    + " default: ${DEFAULT-VALUE}.")
    Format format;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        Integer usage = Files.checkReadable(files, spec);
        if (usage != null) {
            return usage;
        }
        List<Diagnostic> diagnostics = new ModelLoader().check(files);
        PrintWriter out = spec.commandLine().getOut();
        if (format == Format.json) {
            JsonDiagnostics.print(diagnostics, out);
        } else {
            diagnostics.forEach(out::println);
        }
        out.flush();
        return ModelLoader.hasErrors(diagnostics) ? 1 : 0;
    }
}
