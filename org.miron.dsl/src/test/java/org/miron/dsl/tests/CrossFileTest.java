package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;

/**
 * A .miron is checked together with what it imports: loading it loads its imports into the same
 * resource set, and validating every loaded resource reports their errors with their own file,
 * line and column, as `miron check` prints them.
 */
public class CrossFileTest {

    @Test
    public void errorsOfImportedFilesAreReported() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_broken.miron"));
        List<String> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).collect(Collectors.toList());
        assertEquals(String.join("\n", errors), 2, errors.size());
        assertTrue(errors.toString(), errors.contains(
                "broken.roqme:3:25: error: empty range of 'level': lower bound 10 must be less than upper bound 5"));
        assertTrue(errors.toString(), errors.contains(
                "broken.roqme:4:22: error: reference of 'p' must be in [0,1], not 2"));
    }

    @Test
    public void importedResourcesShareTheResourceSet() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_broken.miron"));
        List<String> loaded = resource.getResourceSet().getResources().stream().map(r -> r.getURI().lastSegment())
                .sorted().collect(Collectors.toList());
        assertEquals(List.of("broken.roqme", "tree.bt", "uses_broken.miron"), loaded);
        List<Issue> own = Models.validateAll(resource).stream()
                .filter(i -> i.getUriToProblem().lastSegment().equals("uses_broken.miron")).collect(Collectors.toList());
        assertEquals(List.of(), own);
    }

    /**
     * The imports a file's scopes see are cached until the file changes: an edit in place (as an
     * editor makes it) to the import's alias must re-link against the new alias at once.
     */
    @Test
    public void editingAnImportInPlaceRelinksAgainstIt() throws Exception {
        org.eclipse.xtext.resource.XtextResource resource = (org.eclipse.xtext.resource.XtextResource) Models
                .load(new File("src/test/resources/models/crossfile/uses_broken.miron"));
        assertEquals(List.of(), ownErrors(resource));
        String text = resource.getParseResult().getRootNode().getText();
        int alias = text.indexOf("as b") + 3;
        resource.update(alias, 1, "q"); // import "../lib/broken.roqme" as q
        org.eclipse.emf.ecore.util.EcoreUtil.resolveAll(resource);
        assertTrue(ownErrors(resource).toString(), ownErrors(resource).stream().anyMatch(e -> e.contains("b.level")));
        text = resource.getParseResult().getRootNode().getText();
        int use = text.indexOf("b.level");
        resource.update(use, 1, "q"); // rule r : q.level > 3 ...
        org.eclipse.emf.ecore.util.EcoreUtil.resolveAll(resource);
        assertEquals(List.of(), ownErrors(resource));
    }

    private static List<String> ownErrors(Resource resource) {
        return Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .filter(i -> i.getUriToProblem().lastSegment().equals(resource.getURI().lastSegment()))
                .map(Models::format).collect(Collectors.toList());
    }

    /** Issue 17: a tree repeated with the same content is one tree for references; a different one is ambiguous. */
    @Test
    public void anIdenticallyRepeatedTreeResolvesToTheFirstAndADifferentOneIsAmbiguous() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_dup_trees.miron"));
        List<String> issues = Models.validateAll(resource).stream().map(Models::format).collect(Collectors.toList());
        List<String> own = issues.stream().filter(i -> i.startsWith("uses_dup_trees.miron")).collect(Collectors.toList());
        assertEquals(String.join("\n", issues), 1, own.size());
        assertTrue(own.get(0), own.get(0).contains("t.Wait") && own.get(0).contains("error"));
        assertTrue(issues.toString(), issues.stream().anyMatch(i -> i.startsWith("dup_trees.bt:11:")
                && i.contains("warning") && i.contains("defined twice with the same content")));
        assertTrue(issues.toString(), issues.stream().anyMatch(i -> i.startsWith("dup_trees.bt:17:")
                && i.contains("error") && i.contains("duplicate BehaviorTree ID 'Wait'")));
        org.miron.dsl.miron.BehaviorTreeLiteral charge = org.eclipse.xtext.EcoreUtil2.getAllContentsOfType(
                resource.getContents().get(0), org.miron.dsl.miron.BehaviorTreeLiteral.class).get(0);
        org.miron.bt.bt.BTModel tree = (org.miron.bt.bt.BTModel) charge.getReference().eResource().getContents().get(0);
        assertTrue(charge.getReference() == tree.getTrees().get(1));
    }

    /** Issue 17: a tree without ID is valid BT, and a .miron that tries to name it is told why it cannot. */
    @Test
    public void aTreeWithoutIdCannotBeReferencedAndTheMessageSaysSo() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_unnamed_tree.miron"));
        List<String> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).collect(Collectors.toList());
        assertEquals(List.of("uses_unnamed_tree.miron:4:26: error: unknown behavior tree 't.Main' (the BehaviorTree "
                + "without ID in unnamed_tree.bt cannot be referenced: give it an ID there)"), errors);
    }

    /** Issue 17: a library of several trees is valid alone, but not as the .miron's nominal tree. */
    @Test
    public void aLibraryOfTreesCannotBeTheNominalTree() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_library.miron"));
        List<String> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).collect(Collectors.toList());
        assertEquals(List.of("uses_library.miron:2:1: error: library.bt holds 2 trees and no main_tree_to_execute: "
                + "the woven tree needs to know which one is the main tree (set main_tree_to_execute there)"), errors);
    }
    /** Issue 17: BehaviorTree.CPP's own .xml trees are imported like .bt files, their includes too. */
    @Test
    public void xmlTreesAreImportedLikeBtFiles() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_xml_tree.miron"));
        List<String> issues = Models.validateAll(resource).stream().map(Models::format).collect(Collectors.toList());
        assertEquals(List.of(), issues);
        List<String> loaded = resource.getResourceSet().getResources().stream().map(r -> r.getURI().lastSegment())
                .sorted().collect(Collectors.toList());
        assertEquals(List.of("bt_subtrees.xml", "bt_tree.xml", "uses_xml_tree.miron"), loaded);
    }

    /** An .xml that is not a BehaviorTree.CPP tree is refused with the reason, not "cannot find". */
    @Test
    public void anXmlFileThatIsNotATreeCannotBeImported() {
        Resource resource = Models.load(new File("src/test/resources/models/crossfile/uses_not_a_tree.miron"));
        List<String> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).collect(Collectors.toList());
        assertEquals(List.of("uses_not_a_tree.miron:1:8: error: cannot import 'not_a_tree.xml': it is not a "
                + "BehaviorTree.CPP tree (its root element is not <root>)"), errors);
    }
}
