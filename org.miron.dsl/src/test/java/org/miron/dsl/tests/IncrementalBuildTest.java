package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.build.BuildRequest;
import org.eclipse.xtext.build.IncrementalBuilder;
import org.eclipse.xtext.build.IndexState;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.ExternalContentSupport;
import org.eclipse.xtext.resource.IExternalContentSupport.IExternalContentProvider;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.resource.impl.ChunkedResourceDescriptions;
import org.eclipse.xtext.resource.impl.ResourceDescriptionsData;
import org.eclipse.xtext.validation.Issue;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

import com.google.inject.Injector;

/**
 * Imports go through the Xtext index, as in a language server: Xtext's own incremental builder,
 * with the index carried from one build to the next, revalidates exactly the files that import a
 * changed file, and they see its new content (even unsaved) through the index.
 */
public class IncrementalBuildTest {

    private static final String TREE = """
            <root main_tree_to_execute="Main">
              <include path="inc.bt"/>
              <BehaviorTree ID="Main">
                <Sequence name="mainSeq">
                  <SubTree ID="Dock"/>
                  <Action ID="MoveBase" name="move" speed="0.5"/>
                </Sequence>
              </BehaviorTree>
              <BehaviorTree ID="Careful">
                <Action ID="MoveBase" name="moveSlow" speed="0.2"/>
              </BehaviorTree>
            </root>
            """;

    private static final String INC = """
            <root>
              <BehaviorTree ID="Dock">
                <Action ID="Dock" name="dock"/>
              </BehaviorTree>
            </root>
            """;

    private static final String QOS = """
            roqme Qos
            context battery : number (0:100)
            property safety
            property performance
            """;

    private Injector injector;
    private IndexState index = new IndexState();
    private final Map<String, String> unsaved = new HashMap<>();
    /** File name to its errors, for each file the last build validated. */
    private final Map<String, List<String>> validated = new TreeMap<>();

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Before
    public void setUp() throws IOException {
        injector = Models.injector();
        write("tree.bt", TREE);
        write("inc.bt", INC);
        write("qos.roqme", QOS);
        write("aliased.miron", """
                import "qos.roqme" as q
                import "tree.bt" as main
                @varpoint style : enum { careful : main.Careful affects q.safety++, usual : preset } in main.mainSeq
                """);
        write("namespaced.miron", """
                import "qos.roqme"
                @varpoint level : number (0:1:2) { 0 affects Qos.safety+, 2 affects Qos.performance+ }
                  in arch { parameter "p" component "c" parameterSet "s" parameterSetRepository "r" }
                """);
        write("alone.miron", """
                property comfort
                @varpoint speed : number (1:1:3) { 1 affects comfort+, 3 affects comfort- }
                  in arch { parameter "p" component "c" parameterSet "s" parameterSetRepository "r" }
                """);
        build(List.of("tree.bt", "inc.bt", "qos.roqme", "aliased.miron", "namespaced.miron", "alone.miron"), List.of());
        assertEquals(Set.of("tree.bt", "inc.bt", "qos.roqme", "aliased.miron", "namespaced.miron", "alone.miron"),
                validated.keySet());
        assertNoErrors();
    }

    @Test
    public void renamedPropertyBreaksExactlyItsImporters() throws IOException {
        write("qos.roqme", QOS.replace("property safety", "property security"));
        build(List.of("qos.roqme"), List.of());
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron"), validated.keySet());
        assertEquals(List.of("unknown property 'q.safety'"), validated.get("aliased.miron"));
        assertEquals(List.of("unknown property 'Qos.safety'"), validated.get("namespaced.miron"));
        assertEquals(List.of(), validated.get("qos.roqme"));

        write("qos.roqme", QOS);
        build(List.of("qos.roqme"), List.of());
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron"), validated.keySet());
        assertNoErrors();
    }

    @Test
    public void changedNamespaceChangesThePrefix() throws IOException {
        write("qos.roqme", QOS.replace("roqme Qos", "roqme Quality"));
        build(List.of("qos.roqme"), List.of());
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron"), validated.keySet());
        assertEquals(List.of(), validated.get("aliased.miron"));
        assertEquals(List.of("unknown property 'Qos.safety'", "unknown property 'Qos.performance'"),
                validated.get("namespaced.miron"));
    }

    @Test
    public void renamedTreeBreaksTheImportingMiron() throws IOException {
        write("tree.bt", TREE.replace("\"Careful\"", "\"Cautious\""));
        build(List.of("tree.bt"), List.of());
        assertEquals(Set.of("tree.bt", "aliased.miron"), validated.keySet());
        assertEquals(List.of("unknown behavior tree 'main.Careful'"), validated.get("aliased.miron"));

        write("tree.bt", TREE);
        build(List.of("tree.bt"), List.of());
        assertEquals(Set.of("tree.bt", "aliased.miron"), validated.keySet());
        assertNoErrors();
    }

    @Test
    public void renamedTreeBreaksTheIncludingBt() throws IOException {
        write("inc.bt", INC.replace("\"Dock\"", "\"Park\""));
        build(List.of("inc.bt"), List.of());
        assertTrue(validated.toString(), validated.keySet().containsAll(Set.of("inc.bt", "tree.bt")));
        assertTrue(validated.toString(), !validated.containsKey("alone.miron") && !validated.containsKey("qos.roqme"));
        assertEquals(1, validated.get("tree.bt").size());
        assertTrue(validated.toString(), validated.get("tree.bt").get(0).contains("'Dock'"));

        write("inc.bt", INC);
        build(List.of("inc.bt"), List.of());
        assertTrue(validated.toString(), validated.containsKey("tree.bt"));
        assertNoErrors();
    }

    @Test
    public void deletedImportIsReportedAndRestored() throws IOException {
        Files.delete(file("qos.roqme").toPath());
        build(List.of(), List.of("qos.roqme"));
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron"), validated.keySet());
        assertTrue(validated.toString(), validated.get("aliased.miron").contains(
                "cannot find imported file 'qos.roqme' (paths are relative to this file)"));

        write("qos.roqme", QOS);
        build(List.of("qos.roqme"), List.of());
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron"), validated.keySet());
        assertNoErrors();
    }

    @Test
    public void importersOfAnImporterAreRevalidated() throws IOException {
        write("outer.miron", """
                import "aliased.miron" as a
                rule r : implies a.style = a::style::usual
                """);
        build(List.of("outer.miron"), List.of());
        assertNoErrors();

        write("qos.roqme", QOS.replace("property safety", "property security"));
        build(List.of("qos.roqme"), List.of());
        assertEquals(Set.of("qos.roqme", "aliased.miron", "namespaced.miron", "outer.miron"), validated.keySet());
        assertEquals(List.of(), validated.get("outer.miron"));
    }

    @Test
    public void unsavedContentIsWhatImportersSee() {
        unsaved.put("qos.roqme", QOS.replace("property safety", "property security"));
        build(List.of("qos.roqme"), List.of());
        assertEquals(List.of("unknown property 'q.safety'"), validated.get("aliased.miron"));
    }

    // ------------------------------------------------------------------ a language-server-like build

    private void build(List<String> dirty, List<String> deleted) {
        validated.clear();
        BuildRequest request = new BuildRequest();
        request.setBaseDir(URI.createFileURI(folder.getRoot().getAbsolutePath() + "/"));
        request.setState(new IndexState(index.getResourceDescriptions().copy(), index.getFileMappings().copy()));
        request.setResourceSet(freshResourceSet(request.getState().getResourceDescriptions()));
        request.setDirtyFiles(uris(dirty));
        request.setDeletedFiles(uris(deleted));
        request.setAfterValidate((uri, issues) -> {
            List<String> errors = new ArrayList<>();
            for (Issue issue : issues) {
                if (issue.getSeverity() == Severity.ERROR) {
                    errors.add(issue.getMessage());
                }
            }
            validated.put(uri.lastSegment(), errors);
            return false; // nothing to generate here
        });
        IncrementalBuilder builder = injector.getInstance(IncrementalBuilder.class);
        index = builder.build(request, IResourceServiceProvider.Registry.INSTANCE::getResourceServiceProvider)
                .getIndexState();
    }

    /** As the language server makes one per build: the index attached, editors' content first. */
    private XtextResourceSet freshResourceSet(ResourceDescriptionsData data) {
        XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
        new ChunkedResourceDescriptions(new HashMap<>(Map.of("project", data)), resourceSet);
        new ExternalContentSupport().configureResourceSet(resourceSet, new IExternalContentProvider() {
            @Override
            public String getContent(URI uri) {
                return unsaved.get(uri.lastSegment());
            }

            @Override
            public boolean hasContent(URI uri) {
                return unsaved.containsKey(uri.lastSegment());
            }

            @Override
            public IExternalContentProvider getActualContentProvider() {
                return this;
            }
        });
        return resourceSet;
    }

    private void assertNoErrors() {
        Map<String, List<String>> errors = new TreeMap<>(validated);
        errors.values().removeIf(List::isEmpty);
        assertEquals(Map.of(), errors);
    }

    private List<URI> uris(List<String> names) {
        List<URI> result = new ArrayList<>();
        for (String name : new TreeSet<>(names)) {
            result.add(URI.createFileURI(file(name).getAbsolutePath()));
        }
        return result;
    }

    private File file(String name) {
        return new File(folder.getRoot(), name);
    }

    private void write(String name, String content) throws IOException {
        Files.writeString(file(name).toPath(), content, StandardCharsets.UTF_8);
    }
}
