package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.roqme.DocumentableElement;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.validation.RoqmeIssueCodes;

/**
 * What the model-file tests cannot see: which comments become documentation, and the column at
 * which a bad cron field is reported.
 */
public class CommentsAndTimersTest {

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final File MODELS = new File("src/test/resources/models");

    private static Map<String, String> docs(List<? extends Variable> variables) {
        Map<String, String> docs = new HashMap<>();
        for (Variable v : variables) {
            docs.put(v.getName(), v instanceof DocumentableElement ? ((DocumentableElement) v).getDocumentation() : null);
        }
        return docs;
    }

    @Test
    public void onlyDocCommentsDocumentRoqme() {
        Resource resource = Models.load(new File(MODELS, "roqme/valid/comments.roqme"));
        assertEquals(List.of(), resource.getErrors());
        RoqmeModel model = (RoqmeModel) resource.getContents().get(0);
        assertEquals("/** The model's documentation. */", model.getDocumentation());
        Map<String, String> docs = docs(model.getVariables());
        assertNull("/**/ is a plain comment", docs.get("a"));
        assertNull("/***/ is a plain comment", docs.get("b"));
        assertEquals("/** documents c */", docs.get("c"));
        assertEquals("/**x*/", docs.get("d"));
        assertTrue(docs.get("e"), docs.get("e").startsWith("/**\n * documents e, over"));
        assertNull("a /*** banner ***/ is a plain comment", docs.get("q"));
    }

    @Test
    public void onlyDocCommentsDocumentMiron() {
        Resource resource = Models.load(new File(MODELS, "miron/valid/comments.miron"));
        assertEquals(List.of(), resource.getErrors());
        MironModel model = (MironModel) resource.getContents().get(0);
        assertEquals("/** The model's documentation. */", model.getDocumentation());
        Map<String, String> docs = docs(model.getVariables());
        assertNull(docs.get("zone"));
        assertEquals("/** documented property */", docs.get("safety"));
        assertNull("/*****************/ is a plain comment", docs.get("style"));
    }

    /** Each comment form alone, at the end of the file and before an element, in both languages. */
    @Test
    public void emptyCommentsParseEverywhere() throws IOException {
        for (String ext : List.of("roqme", "miron")) {
            for (String comment : List.of("/**/", "/***/", "/****/", "/** x */", "/* x */", "/*/ x */")) {
                String header = ext.equals("roqme") ? "roqme M\n" : "miron M\n";
                for (String text : List.of(comment + "\n" + header, header + comment + "\n",
                        header + "context a : number " + comment + "\n", header + comment + " context a : number\n")) {
                    File file = temp.newFile("m" + Math.abs(text.hashCode()) + "." + ext);
                    Files.writeString(file.toPath(), text, StandardCharsets.UTF_8);
                    Resource resource = Models.load(file);
                    boolean docAtEnd = comment.startsWith("/** ") && text.endsWith(comment + "\n");
                    if (docAtEnd) {
                        // documentation of nothing is an error, reported as such
                        assertTrue(text, resource.getErrors().get(0).getMessage().contains("a documentation comment"));
                    } else {
                        assertEquals(text, List.of(), resource.getErrors());
                    }
                }
            }
        }
    }

    /** A wrong cron field is underlined where it is, not on the whole schedule. */
    @Test
    public void cronErrorsPointAtTheField() throws IOException {
        File file = temp.newFile("cron.roqme");
        Files.writeString(file.toPath(), "roqme Cron\ntimer a := schedule(\"0 24 * * *\")\n"
                + "timer b := schedule(\"*/5 8-18 * JAN,FEBR *\")\ntimer c := schedule(\"*/0 * * * *\")\n",
                StandardCharsets.UTF_8);
        List<Issue> errors = Models.validateAll(Models.load(file)).stream()
                .filter(i -> i.getSeverity() == Severity.ERROR).collect(Collectors.toList());
        assertEquals(errors.toString(), 3, errors.size());
        for (Issue issue : errors) {
            assertEquals(RoqmeIssueCodes.INVALID_SCHEDULE, issue.getCode());
        }
        // timer a := schedule("0 24 * * *"): '24' starts at column 24
        assertEquals(2, (int) errors.get(0).getLineNumber());
        assertEquals(24, (int) errors.get(0).getColumn());
        assertEquals(2, (int) errors.get(0).getLength());
        // timer b := schedule("*/5 8-18 * JAN,FEBR *"): 'FEBR' at column 37
        assertEquals(37, (int) errors.get(1).getColumn());
        assertEquals(4, (int) errors.get(1).getLength());
        // timer c := schedule("*/0 * * * *"): the step '0' at column 24
        assertEquals(24, (int) errors.get(2).getColumn());
        assertEquals(1, (int) errors.get(2).getLength());
    }
}
