package org.miron.dsl.tests;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.eclipse.xtext.validation.Issue;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.validation.BtIssueCodes;
import org.miron.dsl.validation.MironIssueCodes;
import org.miron.dsl.validation.RoqmeIssueCodes;

/**
 * Every diagnostic of RoQME and MIRoN carries a code: RoqmeIssueCodes in .roqme files,
 * RoqmeIssueCodes or MironIssueCodes in .miron files (MIRoN inherits RoQME's rules), and the
 * BT language's codes in the .bt files they import. An unknown name carries "did you mean" data.
 */
public class IssueCodesTest {
    private static final File MODELS = new File("src/test/resources/models");

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    /** The values of a class's public string constants, read by reflection. */
    static Set<String> codes(Class<?> holder) throws IllegalAccessException {
        Set<String> codes = new HashSet<>();
        for (Field field : holder.getFields()) {
            if (Modifier.isStatic(field.getModifiers()) && field.getType() == String.class) {
                assertTrue(field.getName() + " is written twice", codes.add((String) field.get(null)));
            }
        }
        return codes;
    }

    @Test
    public void codesAreDistinctAndPrefixedWithTheLanguage() throws Exception {
        for (String code : codes(RoqmeIssueCodes.class)) {
            assertTrue(code, code.matches("roqme\\.[a-z0-9]+(-[a-z0-9]+)*"));
        }
        for (String code : codes(MironIssueCodes.class)) {
            assertTrue(code, code.matches("miron\\.[a-z0-9]+(-[a-z0-9]+)*"));
        }
    }

    @Test
    public void everyCodeIsDocumented() throws Exception {
        String doc = Files.readString(new File(Models.root(), "docs/issue-codes.md").toPath());
        Set<String> codes = new HashSet<>(codes(RoqmeIssueCodes.class));
        codes.addAll(codes(MironIssueCodes.class));
        for (String code : codes) {
            assertTrue(code + " is not in docs/issue-codes.md", doc.contains("| `" + code + "` |"));
        }
    }

    @Test
    public void everyIssueOfEveryInvalidModelHasACodeOfItsLanguage() throws Exception {
        Set<String> roqme = codes(RoqmeIssueCodes.class);
        Set<String> miron = new HashSet<>(roqme);
        miron.addAll(codes(MironIssueCodes.class));
        Set<String> bt = codes(BtIssueCodes.class);
        List<String> wrong = new ArrayList<>();
        int issues = 0;
        List<File> files = invalidModels();
        for (File file : files) {
            for (Issue issue : Models.validateAll(Models.load(file))) {
                issues++;
                String in = issue.getUriToProblem().trimFragment().fileExtension();
                Set<String> allowed = "roqme".equals(in) ? roqme : "miron".equals(in) ? miron : bt;
                if (!allowed.contains(issue.getCode())) {
                    wrong.add(file.getName() + ": [" + issue.getCode() + "] " + Models.format(issue));
                }
            }
        }
        assertTrue(files.size() + " files", files.size() > 30);
        assertTrue("only " + issues + " issues", issues >= files.size());
        assertTrue("issues without a code of their language:\n" + String.join("\n", wrong), wrong.isEmpty());
    }

    @Test
    public void aMisspeltNameSuggestsTheClosestVisibleNames() throws IOException {
        File file = write("typo.roqme", "roqme Typo\ncontext battery : number\ncontext batteries : number\n"
                + "context speed : number\nvar v : number := batery + 1\n");
        Issue issue = single(file, RoqmeIssueCodes.UNKNOWN_REFERENCE);
        assertEquals("unknown variable 'batery'", issue.getMessage());
        assertArrayEquals(new String[] { "battery" }, issue.getData());
    }

    @Test
    public void aMisspeltImportedNameSuggestsItWithItsQualifier() throws IOException {
        write("base.roqme", "roqme Base\ncontext battery : number\n");
        File file = write("main.roqme", "roqme Main\nimport \"base.roqme\"\nvar v : number := Base.batery + 1\n");
        Issue issue = single(file, RoqmeIssueCodes.UNKNOWN_REFERENCE);
        assertArrayEquals(new String[] { "Base.battery" }, issue.getData());
    }

    @Test
    public void aNameDeclaredInANamespacedFileNextToItNamesTheImport() throws IOException {
        write("base.roqme", "roqme Base\ncontext battery : number\n");
        File qualified = write("q.roqme", "roqme Q\nvar v : number := Base.battery + 1\n");
        Issue issue = single(qualified, RoqmeIssueCodes.MISSING_IMPORT);
        assertEquals("unknown variable 'Base.battery'", issue.getMessage());
        assertArrayEquals(new String[] { "import \"base.roqme\"", "Base.battery" }, issue.getData());
        File plain = write("p.roqme", "roqme P\nvar v : number := battery + 1\n");
        assertArrayEquals(new String[] { "import \"base.roqme\"", "Base.battery" },
                single(plain, RoqmeIssueCodes.MISSING_IMPORT).getData());
    }

    @Test
    public void anUnknownAliasNamesTheImportOfTheTreeFileNextToIt() throws IOException {
        write("tree.bt", "<root main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence name=\"mainSeq\"><SubTree ID=\"Careful\" name=\"nav\"/></Sequence>\n"
                + "  </BehaviorTree>\n  <BehaviorTree ID=\"Careful\"><AlwaysSuccess/></BehaviorTree>\n</root>\n");
        File model = write("m.miron", "@varpoint mode : enum { careful : t.Careful, nominal : preset } in t.nav\n");
        List<Issue> issues = Models.validateAll(Models.load(model)).stream()
                .filter(i -> RoqmeIssueCodes.MISSING_IMPORT.equals(i.getCode())).collect(Collectors.toList());
        assertEquals(2, issues.size());
        for (Issue issue : issues) {
            assertEquals("import \"tree.bt\" as t", issue.getData()[0]);
        }
        assertEquals(Set.of("t.Careful", "t.nav"), issues.stream().map(i -> i.getData()[1]).collect(Collectors.toSet()));
    }

    @Test
    public void anAlreadyImportedFileIsNotOfferedAgain() throws IOException {
        write("base.roqme", "roqme Base\ncontext battery : number\n");
        File file = write("main.roqme", "roqme Main\nimport \"base.roqme\"\nvar v : number := Base.speed + 1\n");
        single(file, RoqmeIssueCodes.UNKNOWN_REFERENCE);
    }

    @Test
    public void aNameOfAnotherKindHasItsOwnCode() {
        File file = new File(MODELS, "roqme/invalid/unresolved.roqme");
        List<Issue> issues = Models.validateAll(Models.load(file)).stream()
                .filter(i -> RoqmeIssueCodes.WRONG_KIND_REFERENCE.equals(i.getCode())).collect(Collectors.toList());
        assertEquals(1, issues.size());
        assertEquals("unknown belief or property 'a': it is a context, not a belief or property",
                issues.get(0).getMessage());
    }

    @Test
    public void syntaxErrorsHaveTheRoqmeCode() throws IOException {
        File file = write("cut.roqme", "roqme Cut\ncontext battery : \n");
        List<Issue> issues = Models.validateAll(Models.load(file));
        assertTrue(issues.stream().map(Models::format).collect(Collectors.joining("\n")),
                !issues.isEmpty() && issues.stream().allMatch(i -> RoqmeIssueCodes.SYNTAX_ERROR.equals(i.getCode())));
    }

    private File write(String name, String text) throws IOException {
        File file = new File(temp.getRoot(), name);
        Files.writeString(file.toPath(), text);
        return file;
    }

    private static Issue single(File file, String code) {
        List<Issue> issues = Models.validateAll(Models.load(file));
        List<Issue> coded = issues.stream().filter(i -> code.equals(i.getCode())).collect(Collectors.toList());
        assertEquals(issues.stream().map(Models::format).collect(Collectors.joining("\n")), 1, coded.size());
        return coded.get(0);
    }

    private static List<File> invalidModels() throws IOException {
        try (Stream<java.nio.file.Path> paths = Files.walk(MODELS.toPath())) {
            return paths.map(java.nio.file.Path::toFile)
                    .filter(f -> f.getParentFile().getName().equals("invalid"))
                    .filter(f -> f.getName().endsWith(".roqme") || f.getName().endsWith(".miron"))
                    .sorted().collect(Collectors.toList());
        }
    }
}
