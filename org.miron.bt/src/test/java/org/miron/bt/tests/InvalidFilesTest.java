package org.miron.bt.tests;

import static org.junit.Assert.assertFalse;
import static org.junit.Assert.fail;

import java.io.File;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;

/**
 * Each invalid file states the diagnostics it must produce in comments of the form
 * {@code <!-- EXPECT line:column severity: message -->} (the message may be a prefix). Every
 * expectation must be met at exactly that position, and no other error may be reported, except
 * that a file marked {@code <!-- CASCADE -->} (a syntax error) may have follow-on parser errors.
 */
@RunWith(Parameterized.class)
public class InvalidFilesTest {
    private static final Pattern EXPECT = Pattern.compile("<!-- EXPECT (\\d+):(\\d+) (error|warning): (.*?) -->");

    @Parameters(name = "{0}")
    public static Collection<Object[]> files() {
        return BtFiles.filesIn("invalid").stream().map(f -> new Object[] { f.getName(), f })
                .collect(Collectors.toList());
    }

    private final File file;

    public InvalidFilesTest(String name, File file) {
        this.file = file;
    }

    @Test
    public void reportsExactlyTheExpectedDiagnostics() throws Exception {
        List<Issue> issues = BtFiles.validate(BtFiles.load(file));
        List<Issue> unmatched = new ArrayList<>(issues);
        Matcher expectation = EXPECT.matcher(Files.readString(file.toPath()));
        int expectations = 0;
        while (expectation.find()) {
            expectations++;
            int line = Integer.parseInt(expectation.group(1));
            int column = Integer.parseInt(expectation.group(2));
            Severity severity = Severity.valueOf(expectation.group(3).toUpperCase());
            String message = expectation.group(4);
            Issue match = unmatched.stream().filter(i -> i.getLineNumber() == line && i.getColumn() == column
                    && i.getSeverity() == severity && i.getMessage().startsWith(message)).findFirst().orElse(null);
            if (match == null) {
                fail("expected " + expectation.group() + "\nbut got:\n" + BtFiles.describe(issues));
            }
            unmatched.remove(match);
        }
        assertFalse("no EXPECT comment in " + file, expectations == 0);
        if (Files.readString(file.toPath()).contains("<!-- CASCADE -->")) {
            return;
        }
        List<Issue> unexpectedErrors = unmatched.stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .collect(Collectors.toList());
        if (!unexpectedErrors.isEmpty()) {
            fail("unexpected errors:\n" + BtFiles.describe(unexpectedErrors));
        }
    }
}
