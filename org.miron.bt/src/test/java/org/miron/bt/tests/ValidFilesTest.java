package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.serializer.ISerializer;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import org.miron.bt.formatting2.BtFormatting;
import org.miron.testkit.RepositoryRoot;

/**
 * Every valid file (one per language feature, plus the examples) parses and validates without
 * errors, and survives serialization and formatting unchanged as a model.
 */
@RunWith(Parameterized.class)
public class ValidFilesTest {

    @Parameters(name = "{0}")
    public static Collection<Object[]> files() {
        List<File> files = new ArrayList<>(BtFiles.filesIn("valid"));
        files.add(RepositoryRoot.file("examples/intralogistics/intralogistics.bt"));
        return files.stream().map(f -> new Object[] { f.getName(), f }).collect(Collectors.toList());
    }

    private final File file;

    public ValidFilesTest(String name, File file) {
        this.file = file;
    }

    @Test
    public void validatesWithoutErrors() {
        XtextResource resource = BtFiles.load(file);
        List<Issue> errors = BtFiles.validate(resource).stream()
                .filter(issue -> issue.getSeverity() == Severity.ERROR).collect(Collectors.toList());
        assertTrue(BtFiles.describe(errors), errors.isEmpty());
    }

    @Test
    public void serializationRoundTrips() throws Exception {
        XtextResource resource = BtFiles.load(file);
        String text = BtFiles.INJECTOR.getInstance(ISerializer.class).serialize(BtFiles.model(resource));
        XtextResource again = BtFiles.parse(text, file);
        assertTrue(text, again.getErrors().isEmpty());
        assertTrue(text, EcoreUtil.equals(BtFiles.model(resource), BtFiles.model(again)));
    }

    @Test
    public void formattingKeepsTheModelAndIsStable() throws Exception {
        XtextResource resource = BtFiles.load(file);
        String formatted = BtFormatting.format(resource);
        XtextResource again = BtFiles.parse(formatted, file);
        assertTrue(formatted, again.getErrors().isEmpty());
        assertTrue(formatted, EcoreUtil.equals(BtFiles.model(resource), BtFiles.model(again)));
        assertEquals(formatted, BtFormatting.format(again));
    }

    /** Issue 17: what `miron format` writes passes the same checks as the file it formats. */
    @Test
    public void formattedOutputValidatesWithoutErrors() throws Exception {
        String formatted = BtFormatting.format(BtFiles.load(file));
        List<Issue> errors = BtFiles.validate(BtFiles.parse(formatted, file)).stream()
                .filter(issue -> issue.getSeverity() == Severity.ERROR).collect(Collectors.toList());
        assertTrue(formatted + "\n" + BtFiles.describe(errors), errors.isEmpty());
    }
}
