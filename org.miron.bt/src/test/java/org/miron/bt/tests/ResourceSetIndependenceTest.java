package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;

import java.io.File;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.junit.Test;
import org.miron.bt.util.BtTrees;

/**
 * Issue 17: a file's diagnostics do not depend on which other files are loaded with it (an editor
 * with one file open agrees with `miron check` of a whole folder). Every file a valid test file
 * includes is validated alone, after its includer, and before it in the same resource set.
 */
public class ResourceSetIndependenceTest {

    @Test
    public void anIncludedFileIsJudgedTheSameAloneAndWithItsIncluders() {
        int compared = 0;
        for (File includer : BtFiles.filesIn("valid")) {
            for (Resource included : BtTrees.includedResources(BtFiles.load(includer))) {
                File file = new File(included.getURI().toFileString());
                String alone = issues(List.of(file), file);
                assertEquals(file + " after " + includer.getName(), alone, issues(List.of(includer, file), file));
                assertEquals(file + " before " + includer.getName(), alone, issues(List.of(file, includer), file));
                compared++;
            }
        }
        assertFalse("no valid file includes another", compared == 0);
    }

    @Test
    public void aLibraryOfSeveralTreesIsValidAlone() {
        File navigation = new File(BtFiles.RESOURCES, "valid/inc/navigation.bt");
        assertEquals("", issues(List.of(navigation), navigation));
    }

    /** The diagnostics of one file, in a resource set where the given files were loaded in order. */
    private static String issues(List<File> loadOrder, File of) {
        XtextResourceSet set = BtFiles.INJECTOR.getInstance(XtextResourceSet.class);
        List<Resource> loaded = new ArrayList<>();
        for (File f : loadOrder) {
            loaded.add(set.getResource(URI.createFileURI(f.getAbsolutePath()), true));
        }
        EcoreUtil.resolveAll(set);
        Resource target = set.getResource(URI.createFileURI(of.getAbsolutePath()), true);
        return BtFiles.validate(target).stream().map(i -> i.getLineNumber() + ":" + i.getColumn() + " "
                + i.getSeverity() + " " + i.getMessage()).sorted().collect(Collectors.joining("\n"));
    }
}
