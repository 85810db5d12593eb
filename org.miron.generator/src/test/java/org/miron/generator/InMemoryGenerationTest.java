package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.generator.GeneratorContext;
import org.eclipse.xtext.generator.GeneratorDelegate;
import org.eclipse.xtext.generator.InMemoryFileSystemAccess;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.StringInputStream;
import org.junit.Test;
import org.miron.dsl.MironStandaloneSetup;
import org.miron.testkit.JsonSchemaFile;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * MironGenerator as an embedder uses it: models made from strings under non-file URIs (no file on
 * disk), generated into an in-memory file-system access. The woven tree's include is relative to
 * where the target puts it, computed from URIs; a model with an error writes nothing.
 */
public class InMemoryGenerationTest {
    private static final String NOMINAL = """
            <root main_tree_to_execute="Main">
              <BehaviorTree ID="Main">
                <Sequence name="seq">
                  <Action ID="A" name="first"/>
                  <Action ID="B" name="last"/>
                </Sequence>
              </BehaviorTree>
              <BehaviorTree ID="V2">
                <Action ID="X2"/>
              </BehaviorTree>
            </root>
            """;
    private static final String EXTRA = """
            <root>
              <BehaviorTree ID="Extra">
                <Action ID="X3"/>
              </BehaviorTree>
            </root>
            """;
    private static final String MODEL = """
            import "nominal.bt" as bt
            import "lib/extra.bt" as lib

            @varpoint v : enum { a : lib.Extra, b : bt.V2, nominal : preset } before bt.last
            """;

    /** An in-memory target whose files live under folder (as in a workspace or a web editor). */
    private static InMemoryFileSystemAccess locatedAt(String folder) {
        return new InMemoryFileSystemAccess() {
            @Override
            public URI getURI(String path, String outputConfiguration) {
                return URI.createURI(folder + path);
            }
        };
    }

    private static Resource load(XtextResourceSet set, String uri, String text) throws IOException {
        Resource resource = set.createResource(URI.createURI(uri));
        resource.load(new StringInputStream(text, StandardCharsets.UTF_8.name()), null);
        return resource;
    }

    /** nominal.bt, lib/extra.bt and model.miron (with the given text) under base. */
    private static Resource models(String base, String model) throws IOException {
        return models(base, model, NOMINAL);
    }

    private static Resource models(String base, String model, String nominal) throws IOException {
        XtextResourceSet set = MironStandaloneSetup.doSetup().getInstance(XtextResourceSet.class);
        load(set, base + "models/nominal.bt", nominal);
        load(set, base + "models/lib/extra.bt", EXTRA);
        Resource miron = load(set, base + "models/model.miron", model);
        EcoreUtil.resolveAll(set);
        return miron;
    }

    private static String include(CharSequence tree) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("<include path=\"([^\"]*)\"/>").matcher(tree);
        assertTrue(tree.toString(), m.find());
        return m.group(1);
    }

    private static CharSequence file(InMemoryFileSystemAccess fsa, String name) {
        return fsa.getTextFiles().get(InMemoryFileSystemAccess.DEFAULT_OUTPUT + name);
    }

    /** Generates the models under base into fsa; returns the woven tree's include path. */
    private static String generate(String base, InMemoryFileSystemAccess fsa) throws IOException {
        Resource model = models(base, MODEL);
        assertEquals(List.of(), model.getErrors());
        new MironGenerator().doGenerate(model, fsa, new GeneratorContext());

        assertEquals(List.of("model.dzn", "model.ext.xml", "model.io.json", "model.mzn", "model.requirements.json", "model.roqme.json"),
                fsa.getTextFiles().keySet().stream().map(k -> k.replace(InMemoryFileSystemAccess.DEFAULT_OUTPUT, "")).toList());
        assertTrue(file(fsa, "model.ext.xml").toString().contains("<SubTreePlus ID=\"Extra\"/>"));
        assertTrue(file(fsa, "model.mzn").toString().contains("v_var"));
        JsonNode io = new ObjectMapper().readTree(file(fsa, "model.io.json").toString());
        assertEquals("model.ext.xml", io.get("tree").asText());
        assertEquals(List.of(), JsonSchemaFile.IO_JSON.problems(io));
        return include(file(fsa, "model.ext.xml"));
    }

    /**
     * Issue 17: a nominal tree in BehaviorTree.CPP's tutorial form (one tree, no ID) is woven with
     * a tree of another file: BehaviorTree.CPP would count the included tree too, so the woven
     * file names its main tree and says which one it is.
     */
    @Test
    public void anUnnamedMainTreeIsNamedInTheWovenTree() throws IOException {
        String unnamed = """
                <root>
                  <BehaviorTree>
                    <Sequence name="seq">
                      <Action ID="A" name="first"/>
                      <Action ID="B" name="last"/>
                    </Sequence>
                  </BehaviorTree>
                </root>
                """;
        Resource model = models("memory:/", """
                import "nominal.bt" as bt
                import "lib/extra.bt" as lib

                @varpoint v : enum { a : lib.Extra, nominal : preset } before bt.last
                """, unnamed);
        InMemoryFileSystemAccess fsa = new InMemoryFileSystemAccess();
        new MironGenerator().doGenerate(model, fsa, new GeneratorContext());
        String tree = file(fsa, "model.ext.xml").toString();
        assertTrue(tree, tree.contains("<root main_tree_to_execute=\"MainTree\">"));
        assertTrue(tree, tree.contains("<BehaviorTree ID=\"MainTree\">"));
        assertTrue(tree, tree.contains("monitoring_parallel"));
        assertTrue(tree, tree.contains("<SubTreePlus ID=\"Extra\"/>"));
    }

    @Test
    public void generatesIntoMemory() throws IOException {
        // The in-memory access puts its files under memory:/DEFAULT_OUTPUT/.
        assertEquals("../models/lib/extra.bt", generate("memory:/", new InMemoryFileSystemAccess()));
    }

    @Test
    public void includesAreRelativeToWhereTheTargetWrites() throws IOException {
        assertEquals("../models/lib/extra.bt", generate("inmemory:/", locatedAt("inmemory:/out/")));
        assertEquals("../../models/lib/extra.bt", generate("inmemory:/", locatedAt("inmemory:/gen/robot/")));
        assertEquals("lib/extra.bt", generate("inmemory:/", locatedAt("inmemory:/models/")));
        assertEquals("../models/lib/extra.bt", generate("platform:/resource/robot/", locatedAt("platform:/resource/robot/src-gen/")));
    }

    @Test
    public void runsThroughXtextsGeneratorDelegate() throws IOException {
        GeneratorDelegate delegate = MironStandaloneSetup.doSetup().createChildInjector(new MironGeneratorModule())
                .getInstance(GeneratorDelegate.class);
        InMemoryFileSystemAccess fsa = new InMemoryFileSystemAccess();
        delegate.generate(models("memory:/", MODEL), fsa, new GeneratorContext());
        assertEquals(6, fsa.getTextFiles().size()); // with model.requirements.json and model.roqme.json
        assertEquals("../models/lib/extra.bt", include(file(fsa, "model.ext.xml")));
    }

    @Test
    public void includesAcrossSchemesStayAbsolute() throws IOException {
        assertEquals("synthetic:/models/lib/extra.bt", generate("synthetic:/", new InMemoryFileSystemAccess()));
    }

    @Test
    public void aModelWithAGenerationErrorWritesNothing() throws IOException {
        // Validators accept it, but a rule with no MiniZinc meaning (a count over time) cannot be generated.
        String roqme = "roqme R\ncontext Done : eventtype\nproperty safety\n";
        XtextResourceSet set = MironStandaloneSetup.doSetup().getInstance(XtextResourceSet.class);
        load(set, "inmemory:/models/nominal.bt", NOMINAL);
        load(set, "inmemory:/models/r.roqme", roqme);
        Resource model = load(set, "inmemory:/models/model.miron", """
                import "nominal.bt" as bt
                import "r.roqme" as r

                @varpoint v : enum { b : bt.V2, nominal : preset } in bt.last

                rule many : count(r.Done, 10 minutes) > 3 implies v = v::b
                """);
        EcoreUtil.resolveAll(set);
        assertEquals(List.of(), model.getErrors());
        assertNothingWritten(model, "cannot generate MiniZinc");
    }

    /** MiniZinc knows nothing of RoQME's timers and observations: they leave the generated files unchanged. */
    @Test
    public void timersAndObservationsLeaveTheGeneratedFilesUnchanged() throws IOException {
        String timers = """
                context crowded : boolean
                property comfort
                timer tick := 10 minutes
                timer morning := schedule("0 8 * * MON-FRI")
                timer cooldown onetime paused := 30 seconds
                observation o1 : tick while (crowded) undermines comfort
                observation o2 : morning or cooldown reinforces comfort
                observation o3 : crowded { starts cooldown stops tick resumes tick }
                """;
        InMemoryFileSystemAccess plain = new InMemoryFileSystemAccess();
        new MironGenerator().doGenerate(models("memory:/", MODEL), plain, new GeneratorContext());
        InMemoryFileSystemAccess withTimers = new InMemoryFileSystemAccess();
        Resource model = models("memory:/", MODEL + timers);
        assertEquals(List.of(), model.getErrors());
        new MironGenerator().doGenerate(model, withTimers, new GeneratorContext());
        assertEquals(plain.getTextFiles().keySet(), withTimers.getTextFiles().keySet());
        for (String name : List.of("model.mzn", "model.dzn", "model.ext.xml")) {
            assertEquals(name, file(plain, name).toString(), file(withTimers, name).toString());
        }
    }

    /** A rule that reads a timer passes validation (event & boolean is boolean) but has no MiniZinc meaning. */
    @Test
    public void aRuleReadingATimerIsAGenerationError() throws IOException {
        Resource model = models("inmemory:/", MODEL + """
                context crowded : boolean
                timer tick := 10 minutes
                rule r : crowded & tick implies v = v::b
                """);
        assertEquals(List.of(), model.getErrors());
        assertNothingWritten(model, "'tick' is none of them");
    }

    @Test
    public void aModelThatDoesNotLinkWritesNothing() throws IOException {
        assertNothingWritten(models("inmemory:/", MODEL.replace("bt.last", "bt.NoSuchNode")), "NoSuchNode");
    }

    private static void assertNothingWritten(Resource model, String expectedError) {
        InMemoryFileSystemAccess fsa = locatedAt("inmemory:/out/");
        MironGenerator generator = new MironGenerator();
        StagedGeneration staged = generator.stage(model, fsa);
        assertFalse("the model should not generate", staged.succeeded());
        assertTrue(staged.errors().toString(), staged.errors().stream().anyMatch(e -> e.message().contains(expectedError)));
        try {
            generator.doGenerate(model, fsa, new GeneratorContext());
            fail("a model with errors must not generate");
        } catch (GenerationException e) {
            assertEquals(staged.errors().size(), e.errors().size());
        }
        assertEquals("nothing may be written", 0, fsa.getAllFiles().size());
    }
}
