package org.miron.bt.tests;

import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.miron.bt.BtStandaloneSetup;
import org.miron.bt.bt.BTModel;

import com.google.inject.Injector;

/** Loading and validating real BT files for the tests. */
final class BtFiles {
    static final Injector INJECTOR = BtStandaloneSetup.doSetup();
    static final File RESOURCES = new File("src/test/resources/bt");

    private BtFiles() {
    }

    /** The .bt files of a test-resource folder (not its subfolders), sorted. */
    static List<File> filesIn(String folder) {
        File[] files = new File(RESOURCES, folder).listFiles((dir, name) -> name.endsWith(".bt"));
        return Arrays.stream(files).sorted().collect(Collectors.toList());
    }

    static XtextResource load(File file) {
        XtextResourceSet set = INJECTOR.getInstance(XtextResourceSet.class);
        Resource resource = set.getResource(URI.createFileURI(file.getAbsolutePath()), true);
        EcoreUtil.resolveAll(resource);
        return (XtextResource) resource;
    }

    /** Parses text as if it were the given file (so relative includes resolve the same way). */
    static XtextResource parse(String text, File asFile) throws IOException {
        XtextResourceSet set = INJECTOR.getInstance(XtextResourceSet.class);
        Resource resource = set.createResource(URI.createFileURI(asFile.getAbsolutePath()));
        resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), null);
        EcoreUtil.resolveAll(resource);
        return (XtextResource) resource;
    }

    static List<Issue> validate(Resource resource) {
        IResourceValidator validator = INJECTOR.getInstance(IResourceValidator.class);
        return validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl);
    }

    static BTModel model(Resource resource) {
        return (BTModel) resource.getContents().get(0);
    }

    static String describe(List<Issue> issues) {
        return issues.stream().map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getSeverity() + " "
                + i.getMessage()).collect(Collectors.joining("\n"));
    }
}
