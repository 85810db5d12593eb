package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.resource.BtXmlFiles;

/**
 * BehaviorTree.CPP files are .xml: they include each other like .bt files, in any resource set of
 * the BT language (issue 17), and an included .xml that is not a tree is an error, not a crash.
 */
public class XmlFilesTest {
    private static final File XML = new File(BtFiles.RESOURCES, "xml");

    @Test
    public void xmlTreesIncludeXmlTreesTransitively() {
        XtextResource resource = BtFiles.load(new File(XML, "main.xml"));
        List<Issue> issues = BtFiles.validate(resource);
        assertEquals(BtFiles.describe(issues), List.of(), issues);
        BTModel model = BtFiles.model(resource);
        assertNotNull(model.getTrees().get(0));
        List<SubtreeNode> calls = org.eclipse.xtext.EcoreUtil2.getAllContentsOfType(model, SubtreeNode.class);
        assertEquals(List.of("Child", "Sibling"),
                calls.stream().map(c -> c.getBehaviorTree().getName()).collect(Collectors.toList()));
        assertTrue(calls.get(1).getBehaviorTree().eResource().getURI().lastSegment().equals("sibling.xml"));
    }

    @Test
    public void anIncludedXmlFileThatIsNotATreeIsAnError() {
        List<Issue> errors = BtFiles.validate(BtFiles.load(new File(XML, "includes_pom.xml"))).stream()
                .filter(i -> i.getSeverity() == Severity.ERROR).collect(Collectors.toList());
        assertEquals(BtFiles.describe(errors), 1, errors.size());
        assertTrue(errors.get(0).getMessage(), errors.get(0).getMessage().contains("is not a behaviour-tree file"));
    }

    @Test
    public void onlyXmlFilesWhoseRootIsRootAreTrees() {
        assertTrue(BtXmlFiles.looksLikeBehaviourTree(org.eclipse.emf.common.util.URI.createFileURI(
                new File(XML, "main.xml").getAbsolutePath())));
        assertTrue(!BtXmlFiles.looksLikeBehaviourTree(org.eclipse.emf.common.util.URI.createFileURI(
                new File(BtFiles.RESOURCES, "invalid/inc/pom.xml").getAbsolutePath())));
        org.eclipse.xtext.resource.IResourceServiceProvider.Registry languages =
                org.eclipse.xtext.resource.IResourceServiceProvider.Registry.INSTANCE;
        assertNotNull(languages.getResourceServiceProvider(org.eclipse.emf.common.util.URI.createFileURI(
                new File(XML, "sibling.xml").getAbsolutePath())));
        assertNull(languages.getResourceServiceProvider(org.eclipse.emf.common.util.URI.createFileURI(
                new File(BtFiles.RESOURCES, "invalid/inc/pom.xml").getAbsolutePath())));
    }
}
