package org.miron.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.Test;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;
import org.miron.testkit.RepositoryRoot;

/**
 * BehaviorTree.CPP 3.8.7's own trees (docs, examples, tests) with the real library's verdicts
 * (README.md of the corpus): what the library loads, the BT language accepts (warnings allowed);
 * what it rejects, the language rejects or warns about. Every file is loaded from its own folder,
 * so relative includes resolve. Deliberate differences are listed in {@link #KNOWN}, each with its
 * reason.
 */
public class BtcppCorpusTest {
    private static final Path ROOT = RepositoryRoot.path();
    private static final Path VENDORED = ROOT.resolve("tests/src/test/resources/btcpp3-corpus");

    /** file → why our verdict differs from BehaviorTree.CPP 3.8.7's. Keep it tiny. */
    private static final Map<String, String> KNOWN = Map.of();

    @Test
    public void ourVerdictsAreBehaviorTreeCppsVerdicts() throws IOException {
        Path corpus = corpus();
        List<String> falseRejections = new ArrayList<>();
        List<String> falseAcceptances = new ArrayList<>();
        List<String> known = new ArrayList<>();
        List<String[]> rows = manifest(corpus);
        for (String[] row : rows) {
            String file = row[0];
            boolean accept = "accept".equals(row[1]);
            List<Diagnostic> issues = check(corpus.resolve("trees").resolve(file));
            boolean errors = issues.stream().anyMatch(d -> d.severity() == Diagnostic.Severity.ERROR);
            boolean flagged = !issues.isEmpty();
            String disagreement = null;
            if (accept && errors) {
                disagreement = file + ": BehaviorTree.CPP loads it, we say\n    " + issues.stream()
                        .map(Diagnostic::toString).collect(Collectors.joining("\n    "));
                falseRejections.add(disagreement);
            } else if (!accept && !flagged) {
                disagreement = file + ": BehaviorTree.CPP rejects it (" + row[2] + "), we accept it silently";
                falseAcceptances.add(disagreement);
            }
            if (KNOWN.containsKey(file)) {
                known.add(file);
                if (disagreement != null) {
                    falseRejections.remove(disagreement);
                    falseAcceptances.remove(disagreement);
                }
            }
        }
        System.out.println("btcpp corpus: " + rows.size() + " files, " + falseRejections.size()
                + " false rejections, " + falseAcceptances.size() + " false acceptances, " + known.size()
                + " known differences");
        if (!falseRejections.isEmpty() || !falseAcceptances.isEmpty()) {
            fail("disagreements with BehaviorTree.CPP 3.8.7:\n" + String.join("\n", falseRejections) + "\n"
                    + String.join("\n", falseAcceptances));
        }
        assertEquals("a known difference names a file the manifest does not list", KNOWN.size(), known.size());
    }

    /** What `miron check FILE` reports for the file and the files it includes. */
    static List<Diagnostic> check(Path file) {
        ModelLoader loader = new ModelLoader();
        loader.load(file.toFile());
        return loader.validateAll();
    }

    /**
     * The corpus: the copy MIRON_BTCPP3_CORPUS names (system property or environment variable), else
     * the vendored one; a configured copy must equal the vendored one, so a refreshed corpus is
     * noticed until it is copied in.
     */
    static Path corpus() throws IOException {
        String configured = System.getProperty("MIRON_BTCPP3_CORPUS", System.getenv("MIRON_BTCPP3_CORPUS"));
        Path chosen = configured != null ? Path.of(configured).toAbsolutePath() : VENDORED;
        System.out.println("btcpp corpus: reading " + chosen);
        if (!chosen.equals(VENDORED) && Files.isDirectory(VENDORED)) {
            assertEquals("the vendored corpus differs from " + chosen + ": copy it again", listing(chosen),
                    listing(VENDORED));
        }
        assertTrue("no corpus at " + chosen, Files.isRegularFile(chosen.resolve("manifest.tsv")));
        return chosen;
    }

    /** Every file's relative path and content, to compare two copies. */
    private static String listing(Path root) throws IOException {
        try (Stream<Path> files = Files.walk(root)) {
            List<Path> sorted = files.filter(Files::isRegularFile).sorted().collect(Collectors.toList());
            StringBuilder text = new StringBuilder();
            for (Path file : sorted) {
                text.append("== ").append(root.relativize(file)).append('\n')
                        .append(new String(Files.readAllBytes(file), StandardCharsets.UTF_8)).append('\n');
            }
            return text.toString();
        }
    }

    private static List<String[]> manifest(Path corpus) throws IOException {
        List<String> lines = Files.readAllLines(corpus.resolve("manifest.tsv"), StandardCharsets.UTF_8);
        assertEquals("file\tverdict\tmessage\tnote", lines.get(0));
        List<String[]> rows = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            if (!line.isBlank()) {
                rows.add(line.split("\t", -1));
            }
        }
        assertTrue("too few files: " + rows.size(), rows.size() > 50);
        return rows;
    }
}
