package org.miron.cli;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.Callable;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.util.BtTrees;
import org.miron.diagram.Diagram;
import org.miron.diagram.Diagrams;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** `miron render FILE`: the diagram of a tree file or MIRoN model as a standalone SVG (docs/diagrams.md). */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = { "Draws a behaviour-tree file (.bt, .xml, woven .ext.xml) or a MIRoN model as a standalone SVG: "
                + "every tree top-down (ELK layered), node kinds by shape and colour, names and port values as labels, "
                + "SubTree calls linked; for a .miron the nominal tree with its variation points, variants and parameters.",
                "A file with errors is reported as `miron check` reports it and nothing is written." },
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:written", "1:the file has errors", "2:usage error (no such file or tree)" })
public class RenderCommand implements Callable<Integer> {

    @Parameters(arity = "1", paramLabel = "FILE", description = "The tree file or MIRoN model to draw.")
    File file;

    @Option(names = "--tree", paramLabel = "ID", description = "Draw this tree only (default: every tree of the file).")
    String tree;

    @Option(names = { "-o", "--output" }, paramLabel = "OUT.svg", description = "Where to write the SVG (default: standard output).")
    File output;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        Integer usage = Files.checkReadable(List.of(file), spec);
        if (usage != null) {
            return usage;
        }
        PrintWriter err = spec.commandLine().getErr();
        if (file.getName().endsWith(".roqme")) {
            err.println(file + ": error: a RoQME model has no behaviour tree to draw; render its .miron or .bt");
            err.flush();
            return Files.USAGE;
        }
        ModelLoader loader = new ModelLoader();
        Resource resource = loader.load(file);
        List<Diagnostic> errors = loader.validateAll().stream()
                .filter(d -> d.severity() == Diagnostic.Severity.ERROR).toList();
        if (!errors.isEmpty()) {
            errors.forEach(err::println);
            err.flush();
            return 1;
        }
        Diagram diagram = Diagrams.of(resource, tree);
        if (diagram == null) {
            err.println(file + ": error: no tree '" + tree + "' (trees: "
                    + String.join(", ", BtTrees.visibleTrees(resource).keySet()) + ")");
            err.flush();
            return Files.USAGE;
        }
        String svg = Diagrams.svg(diagram);
        if (output == null) {
            PrintWriter out = spec.commandLine().getOut();
            out.print(svg);
            out.flush();
        } else {
            if (output.getAbsoluteFile().getParentFile() != null) {
                output.getAbsoluteFile().getParentFile().mkdirs();
            }
            java.nio.file.Files.writeString(output.toPath(), svg, StandardCharsets.UTF_8);
        }
        return 0;
    }
}
