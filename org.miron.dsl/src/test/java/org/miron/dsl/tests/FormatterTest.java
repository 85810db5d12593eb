package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.junit.Test;
import org.miron.bt.formatting2.BtFormatting;

/**
 * The formatter (what `miron format` runs for any language): formatting keeps the model, adds
 * no error, and formatting twice changes nothing more; the examples are formatter-clean.
 */
public class FormatterTest {

    /** Formats a parsed file as the CLI does (two-space indentation, '\n' line ends). */
    static String format(XtextResource resource) {
        return BtFormatting.format(resource);
    }

    /** Formats a file, checks the result, and returns it. */
    private static String check(File file) throws IOException {
        XtextResource resource = (XtextResource) Models.load(file);
        String once = format(resource);
        XtextResource again = reparse(file, once);
        assertEquals(file + ":\n" + once, List.of(), again.getErrors());
        assertEquals(file + ": formatting is not stable", once, format(again));
        assertEquals(file + ": formatting changed the model", strip(resource), strip(again));
        return once;
    }

    private static XtextResource reparse(File original, String text) throws IOException {
        XtextResourceSet set = Models.injector().getInstance(XtextResourceSet.class);
        URI uri = URI.createFileURI(new File(original.getParentFile(), "formatted_" + original.getName()).getAbsolutePath());
        Resource resource = set.createResource(uri);
        resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
        return (XtextResource) resource;
    }

    /** The model's tokens without layout: what formatting must not change. */
    private static String strip(XtextResource resource) {
        StringBuilder tokens = new StringBuilder();
        for (org.eclipse.xtext.nodemodel.ILeafNode leaf : resource.getParseResult().getRootNode().getLeafNodes()) {
            if (!leaf.isHidden()) {
                tokens.append(leaf.getText()).append(' ');
            }
        }
        return tokens.toString();
    }

    /**
     * Issue 23, item 10: every shipped example is formatter-clean (what an editor's "Format
     * Document" leaves as it is): blocks written on one line, `implies` on its own line, a binding
     * after a blank line, a long condition's line breaks, all kept.
     */
    @Test
    public void theExamplesAreFormatterClean() throws IOException {
        List<String> changed = new ArrayList<>();
        try (Stream<Path> paths = Files.walk(new File(Models.root(), "examples").toPath())) {
            for (Path path : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".roqme")
                    || p.toString().endsWith(".miron")).sorted()::iterator) {
                String formatted = check(path.toFile());
                if (!formatted.equals(Files.readString(path))) {
                    changed.add(path + ":\n" + formatted);
                }
            }
        }
        assertEquals(String.join("\n\n", changed), List.of(), changed);
    }

    @Test
    public void aOneLineRuleGetsImpliesOnItsOwnLine() throws IOException {
        Path example = new File(Models.root(), "examples/intralogistics").toPath();
        Path copy = Files.createTempDirectory("formatter");
        try {
            for (String name : List.of("intralogistics.miron", "intralogistics.roqme", "intralogistics.bt")) {
                Files.copy(example.resolve(name), copy.resolve(name));
            }
            Path model = copy.resolve("intralogistics.miron");
            Files.writeString(model, Files.readString(model).replace("< 0.3\n  implies", "< 0.3 implies")
                    .replace("}\n\nin arch", "} in arch"));
            String formatted = check(model.toFile());
            assertEquals(formatted, true,
                    formatted.contains("rule noBattery : roqme.power_autonomy < 0.3\n  implies task = task::dock\n"));
            assertEquals(formatted, true, formatted.contains("} in arch {"));
            // a requirement's formula stays on its own line, one level in, or on the requirement's line
            Files.writeString(model, Files.readString(model).replace("docksOnLowBattery :\n  always (", "docksOnLowBattery :\n\t\talways  (")
                    .replace("neverStranded : never (", "neverStranded :   never ("));
            formatted = check(model.toFile());
            assertEquals(formatted, true, formatted.contains("requirement docksOnLowBattery :\n  always (roqme.power_autonomy"));
            assertEquals(formatted, true, formatted.contains("requirement neverStranded : never (roqme.BatteryLevel < 1 and"));
        } finally {
            try (Stream<Path> files = Files.walk(copy)) {
                files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    @Test
    public void everyModel() throws IOException {
        List<File> files = new ArrayList<>();
        try (Stream<Path> paths = Files.walk(new File("src/test/resources/models").toPath())) {
            paths.filter(p -> p.getParent().endsWith("valid")).sorted().forEach(p -> files.add(p.toFile()));
        }
        try (Stream<Path> paths = Files.walk(new File(Models.root(), "examples").toPath())) {
            paths.filter(p -> p.toString().endsWith(".roqme") || p.toString().endsWith(".miron")).sorted()
                    .forEach(p -> files.add(p.toFile()));
        }
        List<String> failures = new ArrayList<>();
        for (File file : files) {
            try {
                check(file);
            } catch (AssertionError | RuntimeException e) {
                failures.add(e.toString());
            }
        }
        assertEquals(failures.stream().limit(3).collect(Collectors.joining("\n\n")), 0, failures.size());
    }

    @Test
    public void parenthesesOfCallsAndOfSubExpressions() throws IOException {
        File file = new File("src/test/resources/models/roqme/valid/tool_style.roqme");
        String formatted = check(file);
        assertEquals(formatted, true, formatted.contains(
                "observation d8 : (!Lifted repeat(100)) or (!Charging repeat(50)) reinforces reliability"));
        assertEquals(formatted, true, formatted.contains("observation d5 : eventWhen(Level < 20) undermines"));
    }
}
