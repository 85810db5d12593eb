package org.miron.executor;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.IResourceFactory;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.miron.bt.BtStandaloneSetup;
import org.miron.bt.bt.BTModel;

import com.google.inject.Injector;

/**
 * Loads a .bt or BehaviorTree.CPP .xml file (woven trees too) through the BT language with its includes, and refuses it when
 * the parser, the linker or the validator reports an error, listing them all with their position.
 */
public final class BtLoader {
    private static Injector injector;

    /** The loaded model and the validator's warnings (e.g. spellings current BT.CPP rejects). */
    public record Loaded(BTModel model, List<String> warnings) {
    }

    private static synchronized Injector injector() {
        if (injector == null) {
            injector = BtStandaloneSetup.doSetup();
        }
        return injector;
    }

    public Loaded load(Path file) {
        Path absolute = file.toAbsolutePath().normalize();
        if (!Files.isRegularFile(absolute)) {
            throw new BtBuildException("no such behaviour-tree file: " + absolute);
        }
        XtextResourceSet resourceSet = injector().getInstance(XtextResourceSet.class);
        // Woven trees are written as .ext.xml: parse them with the BT language too, in this
        // resource set only (the global registry keeps "xml" for whoever else uses it).
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap()
                .put("xml", injector().getInstance(IResourceFactory.class));
        Resource resource;
        try {
            resource = resourceSet.getResource(URI.createFileURI(absolute.toString()), true);
        } catch (RuntimeException e) {
            throw new BtBuildException("cannot read " + absolute + ": " + e.getMessage(), e);
        }
        EcoreUtil.resolveAll(resourceSet);
        List<String> errors = new ArrayList<>();
        List<String> warnings = new ArrayList<>();
        IResourceValidator validator = injector().getInstance(IResourceValidator.class);
        for (Resource loaded : new ArrayList<>(resourceSet.getResources())) {
            for (Issue issue : validator.validate(loaded, CheckMode.ALL, CancelIndicator.NullImpl)) {
                String text = describe(loaded, issue);
                if (issue.getSeverity() == Severity.ERROR) {
                    errors.add(text);
                } else if (issue.getSeverity() == Severity.WARNING) {
                    warnings.add(text);
                }
            }
        }
        if (!errors.isEmpty()) {
            throw new BtBuildException("cannot load " + absolute + ":\n  " + String.join("\n  ", errors));
        }
        if (resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof BTModel)) {
            throw new BtBuildException("cannot load " + absolute + ": not a behaviour-tree file");
        }
        return new Loaded((BTModel) resource.getContents().get(0), List.copyOf(warnings));
    }

    private static String describe(Resource resource, Issue issue) {
        String file = resource.getURI().isFile() ? resource.getURI().toFileString() : resource.getURI().toString();
        return file + ":" + issue.getLineNumber() + ":" + issue.getColumn() + ": " + issue.getMessage();
    }
}
