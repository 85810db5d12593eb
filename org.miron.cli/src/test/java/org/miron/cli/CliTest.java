package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;


/** The `miron` command line as a user runs it: exit codes and what it prints. */
public class CliTest {
    private static final File ROOT = new File(System.getProperty("miron.root", ".."));

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private final Cli cli = new Cli();
    private final StringWriter out = cli.out;
    private final StringWriter err = cli.err;

    private int miron(String... args) {
        return cli.run(args);
    }

    private File write(String name, String text) throws IOException {
        File file = new File(temp.getRoot(), name);
        file.getParentFile().mkdirs();
        Files.writeString(file.toPath(), text);
        return file;
    }

    @Test
    public void versionComesFromTheBuildOnEveryCommand() {
        // The version resource is written by the build (build.gradle: versionResource).
        String expected = "miron " + System.getProperty("miron.version", "(miron.version not set by the build)");
        for (String[] args : new String[][] { { "--version" }, { "check", "--version" }, { "broker", "-V" } }) {
            out.getBuffer().setLength(0);
            assertEquals(String.join(" ", args), 0, miron(args));
            assertEquals(String.join(" ", args), expected, out.toString().trim());
        }
    }

    @Test
    public void validExampleChecksClean() {
        assertEquals(0, miron("check", new File(ROOT, "examples/intralogistics/intralogistics.bt").getPath()));
        assertEquals("", out.toString());
    }

    @Test
    public void errorsArePrintedWithFileLineAndColumn() throws IOException {
        File file = write("broken.bt", "<root>\n  <BehaviorTree ID=\"M\">\n    <Inverter/>\n  </BehaviorTree>\n</root>\n");
        assertEquals(1, miron("check", file.getPath()));
        assertEquals(file.getPath()
                + ":3:6: error [bt.decorator-child-count]: Inverter needs exactly one child, it has none\n",
                out.toString().replace(System.lineSeparator(), "\n"));
    }

    @Test
    public void errorsInIncludedFilesAreReportedUnderTheirOwnName() throws IOException {
        write("lib/nav.bt", "<root>\n  <BehaviorTree ID=\"Nav\"><Sequence/></BehaviorTree>\n</root>\n");
        File main = write("main.bt", "<root>\n  <include path=\"lib/nav.bt\"/>\n"
                + "  <BehaviorTree ID=\"Main\"><SubTree ID=\"Nav\"/></BehaviorTree>\n</root>\n");
        assertEquals(1, miron("check", main.getPath()));
        assertTrue(out.toString(), out.toString().contains(
                new File(temp.getRoot(), "lib/nav.bt").getPath()
                        + ":2:27: error [bt.control-without-children]: Sequence needs at least one child"));
    }

    @Test
    public void warningsDoNotFailTheCheck() throws IOException {
        File file = write("old.bt", "<root><BehaviorTree ID=\"M\"><FallbackStar><AlwaysSuccess/></FallbackStar></BehaviorTree></root>");
        assertEquals(0, miron("check", file.getPath()));
        assertTrue(out.toString(), out.toString().startsWith(file.getPath() + ":1:29: warning [bt.fallback-star]: FallbackStar"));
    }

    @Test
    public void aMistypedBlackboardKeyIsAWarning() throws IOException {
        File file = write("typo.bt", "<root main_tree_to_execute=\"M\">\n  <BehaviorTree ID=\"M\"><Sequence>\n"
                + "    <SetBlackboard output_key=\"target\" value=\"dock\"/>\n"
                + "    <Action ID=\"MoveBase\" goal=\"{targte}\" speed=\"{speed}\"/>\n"
                + "  </Sequence></BehaviorTree>\n</root>\n");
        assertEquals(0, miron("check", file.getPath()));
        // {speed} is read and written by nothing too, but no written key is near it: the host may set it
        assertEquals(file.getPath() + ":4:32: warning [bt.key-typo]: nothing in this file or its includes writes "
                + "blackboard key 'targte': did you mean 'target'?\n", out.toString().replace(System.lineSeparator(), "\n"));
    }

    @Test
    public void theHospitalExampleChecksClean() {
        assertEquals(0, miron("check", new File(ROOT, "examples/hospital-delivery/hospital.miron").getPath(),
                new File(ROOT, "examples/hospital-delivery/hospital.bt").getPath()));
        assertEquals("", out.toString());
    }

    @Test
    public void severalFilesAreCheckedTogether() throws IOException {
        File good = write("good.bt", "<root><BehaviorTree ID=\"A\"><AlwaysSuccess/></BehaviorTree></root>");
        File bad = write("bad.xml", "<root><BehaviorTree ID=\"B\"><SubTree ID=\"Nope\"/></BehaviorTree></root>");
        assertEquals(1, miron("check", good.getPath(), bad.getPath()));
        assertTrue(out.toString(),
                out.toString().startsWith(bad.getPath() + ":1:40: error [bt.unknown-subtree]: unknown SubTree ID 'Nope'"));
    }

    @Test
    public void usageErrorsExitWithTwo() throws IOException {
        assertEquals(2, miron());
        assertEquals(2, miron("check"));
        assertEquals(2, miron("check", new File(temp.getRoot(), "missing.bt").getPath()));
        assertTrue(err.toString(), err.toString().contains("missing.bt: error: no such file"));
        assertEquals(2, miron("check", write("notes.txt", "hello").getPath()));
        assertEquals(2, miron("frobnicate"));
    }

    @Test
    public void formatPrintsIndentedXml() throws IOException {
        File file = write("flat.bt", "<root><BehaviorTree ID=\"M\"><Sequence><AlwaysSuccess/></Sequence></BehaviorTree></root>");
        assertEquals(0, miron("format", file.getPath()));
        assertEquals("<root>\n  <BehaviorTree ID=\"M\">\n    <Sequence>\n      <AlwaysSuccess/>\n    </Sequence>\n"
                + "  </BehaviorTree>\n</root>\n", out.toString());
    }

    @Test
    public void formatRefusesFilesThatDoNotParse() throws IOException {
        File file = write("cut.bt", "<root><BehaviorTree ID=\"M\"><Sequence></BehaviorTree></root>");
        assertEquals(1, miron("format", file.getPath()));
        assertEquals("", out.toString());
        assertTrue(err.toString(), err.toString().contains(file.getPath() + ":1:"));
    }

    @Test
    public void formattedExampleChecksClean() throws IOException {
        assertEquals(0, miron("format", new File(ROOT, "examples/intralogistics/intralogistics.bt").getPath()));
        Path copy = new File(ROOT, "examples/intralogistics").toPath().resolve("build-formatted-copy.bt");
        try {
            Files.writeString(copy, out.toString());
            assertEquals(0, miron("check", copy.toString()));
        } finally {
            Files.deleteIfExists(copy);
        }
    }
}
