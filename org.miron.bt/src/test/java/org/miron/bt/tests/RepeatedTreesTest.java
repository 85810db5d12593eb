package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertSame;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;
import org.eclipse.xtext.resource.XtextResource;
import org.junit.Test;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.SubtreeNode;

/**
 * Issue 17: a tree repeated with the same ID and content (a model of the original MIRoN
 * demonstrators does this; BehaviorTree.CPP keeps the first) is one tree for references.
 */
public class RepeatedTreesTest {

    @Test
    public void referencesResolveToTheFirstAndTheRepeatIsNotExported() {
        XtextResource resource = BtFiles.load(new File(BtFiles.RESOURCES, "invalid/warn_duplicate_identical_tree.bt"));
        BTModel model = BtFiles.model(resource);
        SubtreeNode call = EcoreUtil2.getAllContentsOfType(model, SubtreeNode.class).get(0);
        assertSame(model.getTrees().get(1), call.getBehaviorTree());
        IResourceDescription description = resource.getResourceServiceProvider().getResourceDescriptionManager()
                .getResourceDescription(resource);
        List<String> exported = java.util.stream.StreamSupport
                .stream(description.getExportedObjects().spliterator(), false)
                .map(IEObjectDescription::getName).map(Object::toString).collect(Collectors.toList());
        assertEquals(List.of("Main", "Charge"), exported);
    }

    @Test
    public void differentTreesWithOneIdAreBothExported() {
        XtextResource resource = BtFiles.load(new File(BtFiles.RESOURCES, "invalid/duplicate_tree_id.bt"));
        IResourceDescription description = resource.getResourceServiceProvider().getResourceDescriptionManager()
                .getResourceDescription(resource);
        List<String> exported = java.util.stream.StreamSupport
                .stream(description.getExportedObjects().spliterator(), false)
                .map(IEObjectDescription::getName).map(Object::toString).collect(Collectors.toList());
        assertEquals(List.of("Main", "Other", "Main"), exported);
    }
}
