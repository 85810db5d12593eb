package org.miron.dsl.tests;

import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Iterator;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;

/**
 * Every model under src/test/resources/models/{roqme,miron}/{valid,invalid}. A valid model has no
 * error and no unresolved reference. An invalid model marks each expected error on its line with a
 * comment "//! part of the message"; the errors found must be exactly those, on those lines. In
 * both kinds, "//? part of the message" marks an expected warning, and the warnings of the file
 * must be exactly the marked ones. Files under models/lib are only imported by the others.
 */
@RunWith(Parameterized.class)
public class ModelFilesTest {

    private static final Pattern ERROR_MARKER = Pattern.compile("//!\\s*(.+?)\\s*$");
    private static final Pattern WARNING_MARKER = Pattern.compile("//\\?\\s*(.+?)\\s*$");

    @Parameters(name = "{0}")
    public static Collection<Object[]> files() throws IOException {
        File base = new File("src/test/resources/models");
        try (Stream<java.nio.file.Path> paths = Files.walk(base.toPath())) {
            return paths.map(java.nio.file.Path::toFile)
                    .filter(f -> f.getName().endsWith(".roqme") || f.getName().endsWith(".miron"))
                    .filter(f -> f.getParentFile().getName().equals("valid") || f.getParentFile().getName().equals("invalid"))
                    .sorted()
                    .map(f -> new Object[] { base.toPath().relativize(f.toPath()).toString(), f })
                    .collect(Collectors.toList());
        }
    }

    private final File file;

    public ModelFilesTest(String name, File file) {
        this.file = file;
    }

    @Test
    public void check() throws IOException {
        Resource resource = Models.load(file);
        List<Issue> issues = Models.validateAll(resource);
        List<Issue> errors = issues.stream().filter(i -> i.getSeverity() == Severity.ERROR).collect(Collectors.toList());
        List<String> lines = Files.readAllLines(file.toPath(), StandardCharsets.UTF_8);
        List<String> problems = new ArrayList<>();
        expect(WARNING_MARKER, lines, inThisFile(issues, Severity.WARNING), "warning", problems);
        boolean valid = file.getParentFile().getName().equals("valid");
        if (valid) {
            if (!errors.isEmpty()) {
                problems.add("unexpected errors:\n" + errors.stream().map(Models::format).collect(Collectors.joining("\n")));
            }
            List<String> unresolved = Models.unresolved(resource);
            assertTrue("unresolved references: " + unresolved, unresolved.isEmpty());
        } else {
            int errorMarkers = expect(ERROR_MARKER, lines, inThisFile(issues, Severity.ERROR), "error", problems);
            assertTrue(file + " has no //! marker", errorMarkers > 0);
        }
        if (!problems.isEmpty()) {
            fail(String.join("\n", problems) + "\nall issues:\n"
                    + issues.stream().map(Models::format).collect(Collectors.joining("\n")));
        }
    }

    private List<Issue> inThisFile(List<Issue> issues, Severity severity) {
        return issues.stream().filter(i -> i.getSeverity() == severity)
                .filter(i -> i.getUriToProblem().trimFragment().lastSegment().equals(file.getName()))
                .collect(Collectors.toList());
    }

    /**
     * Matches the issues against the markers of one kind, one issue per marker on the marker's
     * line; adds a problem for each marker without its issue and each issue without a marker.
     * Returns the number of markers.
     */
    private static int expect(Pattern marker, List<String> lines, List<Issue> issues, String kind, List<String> problems) {
        List<Issue> remaining = new ArrayList<>(issues);
        int markers = 0;
        for (int n = 0; n < lines.size(); n++) {
            Matcher m = marker.matcher(lines.get(n));
            if (!m.find()) {
                continue;
            }
            markers++;
            String expected = m.group(1);
            int line = n + 1;
            Issue match = null;
            for (Iterator<Issue> it = remaining.iterator(); it.hasNext();) {
                Issue issue = it.next();
                if (issue.getLineNumber() == line && issue.getMessage().contains(expected)) {
                    match = issue;
                    it.remove();
                    break;
                }
            }
            if (match == null) {
                problems.add("line " + line + ": expected " + kind + " containing '" + expected + "'");
            }
        }
        for (Issue issue : remaining) {
            problems.add("unexpected " + Models.format(issue));
        }
        return markers;
    }
}
