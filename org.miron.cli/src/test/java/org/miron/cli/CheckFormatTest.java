package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.RepositoryRoot;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;


/** `miron check` on real files: issue codes in the text lines, and `--format json` for tools. */
public class CheckFormatTest {
    private static final File ROOT = RepositoryRoot.path().toFile();
    private static final ObjectMapper JSON = new ObjectMapper();

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private final Cli cli = new Cli();
    private final StringWriter out = cli.out;
    private final StringWriter err = cli.err;

    private int miron(String... args) {
        return cli.run(args);
    }

    private File write(String name, String text) throws IOException {
        return Cli.write(temp.getRoot().toPath(), name, text).toFile();
    }

    private List<JsonNode> jsonLines() throws IOException {
        List<JsonNode> nodes = new ArrayList<>();
        for (String line : out.toString().split("\\R")) {
            if (!line.isEmpty()) {
                nodes.add(JSON.readTree(line));
            }
        }
        return nodes;
    }

    /**
     * Issue 17: BehaviorTree.CPP's .xml trees include each other (no stack trace, no error), a tree
     * needs no ID when it is the file's only one, and an included .xml that is not a tree is an
     * error at the include; a library of several trees checks the same alone and with its includer.
     */
    @Test
    public void xmlTreesIncludeEachOtherAndVerdictsDoNotDependOnWhatElseIsChecked() throws IOException {
        File child = write("child/child.xml", "<root main_tree_to_execute=\"Child\">\n"
                + "  <BehaviorTree ID=\"Child\"><AlwaysSuccess/></BehaviorTree>\n"
                + "  <BehaviorTree ID=\"Other\"><AlwaysFailure/></BehaviorTree>\n</root>\n");
        File main = write("main.xml", "<root>\n  <include path=\"child/child.xml\"/>\n"
                + "  <BehaviorTree><SubTree ID=\"Child\"/></BehaviorTree>\n</root>\n");
        File library = write("lib.xml", "<root>\n  <BehaviorTree ID=\"A\"><AlwaysSuccess/></BehaviorTree>\n"
                + "  <BehaviorTree ID=\"B\"><AlwaysSuccess/></BehaviorTree>\n</root>\n");
        File user = write("user.xml", "<root main_tree_to_execute=\"U\">\n  <include path=\"lib.xml\"/>\n"
                + "  <BehaviorTree ID=\"U\"><SubTree ID=\"A\"/></BehaviorTree>\n</root>\n");
        assertEquals(out + "" + err, 0, miron("check", main.getPath()));
        assertEquals(out + "" + err, 0, miron("check", library.getPath()));
        assertEquals(out + "" + err, 0, miron("check", user.getPath(), library.getPath()));
        assertEquals(out + "" + err, 0, miron("check", library.getPath(), user.getPath()));
        assertEquals("", out.toString() + err);
        write("pom.xml", "<project><modelVersion>4.0.0</modelVersion></project>\n");
        File broken = write("includes_pom.xml", "<root>\n  <include path=\"pom.xml\"/>\n"
                + "  <BehaviorTree><AlwaysSuccess/></BehaviorTree>\n</root>\n");
        assertEquals(1, miron("check", broken.getPath()));
        assertTrue(out.toString(), out.toString().contains(
                "includes_pom.xml:2:17: error [bt.include-not-bt]: included file 'pom.xml' is not a behaviour-tree file"));
        assertFalse(out + "" + err, (out + "" + err).contains("Exception"));
    }

    @Test
    public void textLinesCarryTheCodeOfErrorsAndWarnings() throws IOException {
        File file = write("mixed.bt", "<root>\n  <BehaviorTree ID=\"M\">\n    <Sequence>\n"
                + "      <RetryUntilSuccesful num_attempts=\"2\"><AlwaysSuccess/></RetryUntilSuccesful>\n"
                + "      <Inverter/>\n    </Sequence>\n  </BehaviorTree>\n</root>\n");
        assertEquals(1, miron("check", file.getPath()));
        assertEquals(file.getPath() + ":4:8: warning [bt.retry-old-spelling]: RetryUntilSuccesful is the BehaviorTree.CPP"
                + " 3.5-3.6 spelling; 3.7 and later only load RetryUntilSuccessful\n"
                + file.getPath() + ":5:8: error [bt.decorator-child-count]: Inverter needs exactly one child, it has none\n",
                out.toString().replace(System.lineSeparator(), "\n"));
    }

    @Test
    public void textIsTheDefaultAndCanBeAskedFor() throws IOException {
        File file = write("broken.bt", "<root><BehaviorTree ID=\"M\"><Inverter/></BehaviorTree></root>");
        assertEquals(1, miron("check", "--format", "text", file.getPath()));
        String explicit = out.toString();
        out.getBuffer().setLength(0);
        assertEquals(1, miron("check", file.getPath()));
        assertEquals(explicit, out.toString());
    }

    @Test
    public void jsonGivesOneObjectPerDiagnosticWithPositionCodeAndData() throws IOException {
        File file = write("typo.bt", "<root main_tree_to_execute=\"Main\">\n"
                + "  <BehaviorTree ID=\"Main\">\n    <Sequence>\n      <SubTree ID=\"Navigat\"/>\n"
                + "      <RetryUntilSuccesful num_attempts=\"2\"><AlwaysSuccess/></RetryUntilSuccesful>\n"
                + "    </Sequence>\n  </BehaviorTree>\n"
                + "  <BehaviorTree ID=\"Navigate\"><AlwaysSuccess/></BehaviorTree>\n</root>\n");
        assertEquals(1, miron("check", "--format", "json", file.getPath()));
        List<JsonNode> diagnostics = jsonLines();
        assertEquals(out.toString(), 2, diagnostics.size());

        JsonNode unknown = diagnostics.get(0);
        assertEquals(file.getPath(), unknown.get("file").asText());
        assertEquals(4, unknown.get("line").asInt());
        assertEquals(19, unknown.get("column").asInt());
        assertEquals(4, unknown.get("endLine").asInt());
        assertEquals(19 + "\"Navigat\"".length(), unknown.get("endColumn").asInt());
        assertEquals("error", unknown.get("severity").asText());
        assertEquals("bt.unknown-subtree", unknown.get("code").asText());
        assertEquals("unknown SubTree ID 'Navigat': no BehaviorTree with this ID in this file or the files it includes",
                unknown.get("message").asText());
        assertEquals("[\"Navigate\"]", unknown.get("data").toString());

        JsonNode retry = diagnostics.get(1);
        assertEquals("warning", retry.get("severity").asText());
        assertEquals("bt.retry-old-spelling", retry.get("code").asText());
        assertEquals("[\"RetryUntilSuccessful\"]", retry.get("data").toString());
    }

    @Test
    public void jsonLeavesOutDataWhenThereIsNone() throws IOException {
        File file = write("broken.bt", "<root><BehaviorTree ID=\"M\"><Inverter/></BehaviorTree></root>");
        assertEquals(1, miron("check", "--format", "json", file.getPath()));
        JsonNode diagnostic = jsonLines().get(0);
        assertEquals("bt.decorator-child-count", diagnostic.get("code").asText());
        assertFalse(diagnostic.toString(), diagnostic.has("data"));
    }

    @Test
    public void jsonOfAMironModelCarriesTheDidYouMeanName() throws IOException {
        write("base.roqme", "roqme Base\ncontext battery : number (0:100)\nproperty safety\n");
        File model = write("m.miron", "import \"base.roqme\"\n\n@varpoint speed : number (0:0.5:1)\n\n"
                + "rule r : Base.batery < 20 implies speed = 0.5\n");
        assertEquals(1, miron("check", "--format", "json", model.getPath()));
        List<JsonNode> diagnostics = jsonLines();
        assertEquals(out.toString(), 1, diagnostics.size());
        assertEquals(5, diagnostics.get(0).get("line").asInt());
        assertEquals("roqme.unknown-reference", diagnostics.get(0).get("code").asText());
        assertEquals("[\"Base.battery\"]", diagnostics.get(0).get("data").toString());
    }

    @Test
    public void validFilesPrintNothingInJson() {
        assertEquals(0, miron("check", "--format", "json",
                new File(ROOT, "examples/intralogistics/intralogistics.miron").getPath()));
        assertEquals("", out.toString());
    }

    @Test
    public void warningsAloneExitWithZeroInJson() throws IOException {
        File file = write("old.bt", "<root><BehaviorTree ID=\"M\"><FallbackStar><AlwaysSuccess/></FallbackStar></BehaviorTree></root>");
        assertEquals(0, miron("check", "--format", "json", file.getPath()));
        JsonNode warning = jsonLines().get(0);
        assertEquals("bt.fallback-star", warning.get("code").asText());
        assertEquals("[\"Fallback\",\"ReactiveFallback\"]", warning.get("data").toString());
    }

    @Test
    public void anUnknownFormatIsAUsageError() throws IOException {
        File file = write("good.bt", "<root><BehaviorTree ID=\"A\"><AlwaysSuccess/></BehaviorTree></root>");
        assertEquals(2, miron("check", "--format", "xml", file.getPath()));
        assertTrue(err.toString(), err.toString().contains("--format"));
        assertEquals("", out.toString());
    }
}
