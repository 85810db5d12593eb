package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.bt.BTModel;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

/** `miron convert` on real files: v3 example to v4 and back, errors with positions and codes. */
public class ConvertCommandTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static BTModel load(File file) {
        return (BTModel) new ModelLoader().load(file).getContents().get(0);
    }

    @Test
    public void convertsTheExampleToVersion4AndBack() throws Exception {
        File example = Cli.ROOT.resolve("org.miron.bt/src/test/resources/bt/valid/woven_like.bt").toFile();
        File v4 = tmp.newFile("woven_like.bt");
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 0, cli.run("convert", "--to", "4", example.getPath(), "-o", v4.getPath()));
        String text = Files.readString(v4.toPath());
        assertTrue(text, text.startsWith("<?xml version=\"1.0\"?>\n<root BTCPP_format=\"4\""));
        assertTrue(text, !text.contains("\n\n"));
        assertTrue(text, text.contains("success_count=\"1\""));
        ModelLoader loader = new ModelLoader();
        loader.load(v4);
        List<Diagnostic> errors = loader.validateAll().stream()
                .filter(d -> d.severity() == Diagnostic.Severity.ERROR).toList();
        assertTrue(errors.toString(), errors.isEmpty());

        Cli back = new Cli();
        assertEquals(back.err.toString(), 0, back.run("convert", "--to", "3", v4.getPath()));
        File v3 = tmp.newFile("again.bt");
        Files.writeString(v3.toPath(), back.out(), StandardCharsets.UTF_8);
        assertTrue(back.out(), EcoreUtil.equals(load(example), load(v3)));
    }

    /** Only what changes is rewritten: the file's comments and layout come through. */
    @Test
    public void theFileKeepsItsComments() throws Exception {
        File example = Cli.ROOT.resolve("org.miron.bt/src/test/resources/bt/valid/prolog_and_comments.bt").toFile();
        String original = Files.readString(example.toPath());
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 0, cli.run("convert", "--to", "4", example.getPath()));
        assertEquals(original.replace("<root main_tree_to_execute", "<root BTCPP_format=\"4\" main_tree_to_execute"),
                cli.out());
    }

    @Test
    public void elementsWithoutEquivalentAreErrorsWithPositionAndCode() throws Exception {
        File file = tmp.newFile("scripted.bt");
        Files.writeString(file.toPath(), "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence>\n      <Script code=\"a := 1\"/>\n      <AlwaysSuccess/>\n    </Sequence>\n"
                + "  </BehaviorTree>\n</root>\n", StandardCharsets.UTF_8);
        Cli cli = new Cli();
        assertEquals(1, cli.run("convert", "--to", "3", file.getPath()));
        assertTrue(cli.err.toString(), cli.err.toString().contains(
                "scripted.bt:4:7: error [bt.no-v3-equivalent]: Script has no BehaviorTree.CPP 3 equivalent"));
        assertEquals("", cli.out());
    }

    @Test
    public void invalidFilesAndUsageErrors() throws Exception {
        File broken = tmp.newFile("broken.bt");
        Files.writeString(broken.toPath(), "<root>\n  <BehaviorTree ID=\"Main\"><Inverter/></BehaviorTree>\n</root>\n",
                StandardCharsets.UTF_8);
        Cli cli = new Cli();
        assertEquals(1, cli.run("convert", "--to", "4", broken.getPath()));
        assertTrue(cli.err.toString(), cli.err.toString().contains("broken.bt:2:28: error [bt.decorator-child-count]"));
        assertEquals(2, Cli.exit("convert", "--to", "5", broken.getPath()));
        assertEquals(2, Cli.exit("convert", broken.getPath()));
        assertEquals(2, Cli.exit("convert", "--to", "4", new File(tmp.getRoot(), "missing.bt").getPath()));
        assertEquals(2, Cli.exit("convert", "--to", "4", broken.getPath(), broken.getPath())); // several: --in-place
        assertEquals(2, Cli.exit("convert", "--to", "4", "--in-place", "-o", "x.bt", broken.getPath()));
    }

    /** A project's trees migrated at once; an include keeps resolving, comments stay. */
    @Test
    public void severalFilesAreRewrittenInPlace() throws Exception {
        File lib = tmp.newFile("lib.bt");
        Files.writeString(lib.toPath(), "<root>\n  <!-- shared -->\n  <BehaviorTree ID=\"Go\">\n"
                + "    <SequenceStar><AlwaysSuccess/></SequenceStar>\n  </BehaviorTree>\n</root>\n", StandardCharsets.UTF_8);
        File main = tmp.newFile("main.bt");
        Files.writeString(main.toPath(), "<root main_tree_to_execute=\"Main\">\n  <include path=\"lib.bt\"/>\n"
                + "  <BehaviorTree ID=\"Main\">\n    <SubTreePlus ID=\"Go\"/> <!-- go -->\n  </BehaviorTree>\n</root>\n",
                StandardCharsets.UTF_8);
        Cli cli = new Cli();
        assertEquals(cli.err.toString(), 0, cli.run("convert", "--to", "4", "-i", lib.getPath(), main.getPath()));
        assertEquals("", cli.out());
        assertTrue(cli.err.toString(), cli.err.toString().contains("wrote " + lib) && cli.err.toString().contains("wrote " + main));
        assertEquals("<root BTCPP_format=\"4\">\n  <!-- shared -->\n  <BehaviorTree ID=\"Go\">\n"
                + "    <SequenceWithMemory><AlwaysSuccess/></SequenceWithMemory>\n  </BehaviorTree>\n</root>\n",
                Files.readString(lib.toPath()));
        assertEquals("<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n  <include path=\"lib.bt\"/>\n"
                + "  <BehaviorTree ID=\"Main\">\n    <SubTree ID=\"Go\" _autoremap=\"false\"/> <!-- go -->\n"
                + "  </BehaviorTree>\n</root>\n", Files.readString(main.toPath()));
        ModelLoader loader = new ModelLoader();
        loader.load(main);
        assertTrue(loader.validateAll().toString(), loader.validateAll().stream()
                .noneMatch(d -> d.severity() == Diagnostic.Severity.ERROR));
        // converted again: nothing to do, nothing written
        Cli again = new Cli();
        assertEquals(0, again.run("convert", "--to", "4", "-i", lib.getPath(), main.getPath()));
        assertEquals("", again.err.toString());
    }

    /** All or nothing: one file that cannot be converted, and no file is written. */
    @Test
    public void oneFileWithoutEquivalentAndNoneIsWritten() throws Exception {
        File plain = tmp.newFile("plain.bt");
        String plainText = "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"A\"><SequenceWithMemory><AlwaysSuccess/>"
                + "</SequenceWithMemory></BehaviorTree>\n</root>\n";
        Files.writeString(plain.toPath(), plainText, StandardCharsets.UTF_8);
        File scripted = tmp.newFile("scripted4.bt");
        String scriptedText = "<root BTCPP_format=\"4\">\n  <BehaviorTree ID=\"B\"><Script code=\"a := 1\"/></BehaviorTree>\n</root>\n";
        Files.writeString(scripted.toPath(), scriptedText, StandardCharsets.UTF_8);
        Cli cli = new Cli();
        assertEquals(1, cli.run("convert", "--to", "3", "--in-place", plain.getPath(), scripted.getPath()));
        assertTrue(cli.err.toString(), cli.err.toString().contains("scripted4.bt:2:24: error [bt.no-v3-equivalent]"));
        assertEquals(plainText, Files.readString(plain.toPath()));
        assertEquals(scriptedText, Files.readString(scripted.toPath()));
    }
}
