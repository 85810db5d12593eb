package org.miron.generator;

import static org.junit.Assert.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized;
import org.junit.runners.Parameterized.Parameters;
import org.miron.testkit.JsonSchemaFile;

/**
 * Golden files of the weaver, one per insertion case (src/test/resources/weaving): each
 * expected tree was written by hand from docs/generators.md, and every woven tree must pass
 * `miron check`; every io.json must follow docs/io-json.schema.json.
 */
@RunWith(Parameterized.class)
public class WeaverGoldenTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static Path models;
    private static Path out;

    @Parameters(name = "{0}")
    public static List<String> cases() {
        return List.of(
                "in_first",         // in: the target becomes the Switch's default child
                "in_middle",
                "in_last",
                "in_root",          // in: the root of the main tree, inside the monitoring Parallel
                "in_wiring",        // in: a subtree call, whose port wiring the variants inherit
                "before_first",     // before the first child; a single case pads a Switch2
                "before_middle",
                "before_last",      // before the last child
                "after_first",
                "after_last",       // after the last child
                "after_middle",     // after the second-to-last child
                "before_tree_root", // before the root of a tree: wrapped in a Sequence
                "after_tree_root",
                "after_decorated",  // after a decorator's only child: wrapped in a Sequence
                "nested",           // 7 cases: Switch5 whose default is a Switch2
                "include",          // a variant tree in another file: <include>, not copied
                "include_twice",    // ... already included by the nominal tree: included once
                "port",             // numeric varpoint bound to an attribute: {speed}, no monitoring
                "two_targets",      // one varpoint, two targets: a Switch at each
                "two",              // two enum varpoints: both monitored
                "deep");            // a port and a Switch in subtrees: keys remapped on the calls above them

    }

    private final String name;

    public WeaverGoldenTest(String name) {
        this.name = name;
    }

    @BeforeClass
    public static void copyModels() throws IOException {
        models = Toolchain.copyResources("weaving", temp.newFolder("models").toPath());
        out = temp.getRoot().toPath().resolve("out");
    }

    @Test
    public void wovenTreeIsTheExpectedOne() throws IOException {
        Toolchain toolchain = new Toolchain();
        int exit = toolchain.generate(models.resolve(name + ".miron").toString(), out.toString());
        assertEquals(toolchain.messages(), 0, exit);
        String expected = Files.readString(models.resolve("expected/" + name + ".ext.xml"));
        assertEquals(expected, Files.readString(out.resolve(name + ".ext.xml")));
    }

    @Test
    public void ioJsonFollowsTheSchema() throws IOException {
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0, toolchain.generate(models.resolve(name + ".miron").toString(), out.toString()));
        JsonSchemaFile.IO_JSON.assertValid(out.resolve(name + ".io.json"));
        JsonSchemaFile.REQUIREMENTS.assertValid(out.resolve(name + ".requirements.json"));
    }

    @Test
    public void wovenTreePassesOurBtValidation() {
        Toolchain generate = new Toolchain();
        assertEquals(0, generate.generate(models.resolve(name + ".miron").toString(), out.toString()));
        Toolchain check = new Toolchain();
        int exit = check.check(out.resolve(name + ".ext.xml").toString());
        assertEquals(check.messages(), 0, exit);
    }
}
