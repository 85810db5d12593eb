package org.miron.generator.standalone;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.LineAndColumn;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceFactory;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.Issue;
import org.miron.bt.BtStandaloneSetup;
import org.miron.dsl.MironStandaloneSetup;

import com.google.inject.Injector;

/**
 * Loads model files of any MIRoN language into one resource set, with everything they import,
 * and validates all of them. The language of a file is chosen by its extension.
 */
public class ModelLoader {
    /** Woven trees are written as name.ext.xml and are BT files too. */
    private static final Set<String> EXTENSIONS = Set.of("bt", "xml", "roqme", "miron");

    private final XtextResourceSet resourceSet;
    private final Path baseDir;

    /** File names in diagnostics are relative to the working directory (a command line's view). */
    public ModelLoader() {
        this(Path.of(""));
    }

    /**
     * File names in diagnostics are relative to baseDir when inside it: a build tool's project
     * folder, whatever the JVM's working directory (a Gradle daemon's is not the user's).
     */
    public ModelLoader(Path baseDir) {
        this.baseDir = baseDir.toAbsolutePath().normalize();
        // Only BT up front: `check` of tree files never pays for RoQME and MIRoN (see load).
        Injector bt = BtStandaloneSetup.doSetup();
        resourceSet = bt.getInstance(XtextResourceSet.class);
        resourceSet.getResourceFactoryRegistry().getExtensionToFactoryMap()
                .put("xml", bt.getInstance(XtextResourceFactory.class));
    }

    /** Sets up what a file's language needs: MIRoN's set-up also registers RoQME (and BT). */
    private static void setUpFor(File file) {
        String name = file.getName();
        if (name.endsWith(".miron") || name.endsWith(".roqme")) {
            MironStandaloneSetup.doSetup(); // one injector per process: cheap after the first
        }
    }

    public static boolean supports(String fileName) {
        int dot = fileName.lastIndexOf('.');
        return dot >= 0 && EXTENSIONS.contains(fileName.substring(dot + 1));
    }

    public static String supportedExtensions() {
        return ".bt or .xml (BehaviorTree.CPP trees, woven trees), .roqme or .miron";
    }

    public XtextResourceSet resourceSet() {
        return resourceSet;
    }

    /** Loads a file (which must exist) and resolves all its references. */
    public Resource load(File file) {
        setUpFor(file);
        Resource resource = resourceSet.getResource(URI.createFileURI(file.getAbsolutePath()), true);
        EcoreUtil.resolveAll(resource);
        return resource;
    }

    /**
     * What `miron check` does: loads the files (which must exist) with everything they import and
     * validates them all, every check.
     */
    public List<Diagnostic> check(List<File> files) {
        files.forEach(this::load);
        return validateAll();
    }

    /** Whether any of the diagnostics is an error (a warning fails nothing). */
    public static boolean hasErrors(List<Diagnostic> diagnostics) {
        return diagnostics.stream().anyMatch(d -> d.severity() == Diagnostic.Severity.ERROR);
    }

    /** Validates every resource loaded so far (the given files and what they import), every check. */
    public List<Diagnostic> validateAll() {
        return validateAll(CheckMode.ALL);
    }

    /**
     * Validates with the checks of a mode: {@code NORMAL_AND_FAST} leaves out the expensive ones
     * (the rule check, docs/issue-codes.md), which `miron generate` does not need.
     */
    public List<Diagnostic> validateAll(CheckMode mode) {
        // Validation may load more files (includes found while linking): iterate over a snapshot.
        EcoreUtil.resolveAll(resourceSet);
        Set<Diagnostic> diagnostics = new TreeSet<>();
        for (Resource resource : new ArrayList<>(resourceSet.getResources())) {
            if (!(resource instanceof XtextResource)) {
                continue;
            }
            List<Issue> issues = ((XtextResource) resource).getResourceServiceProvider().getResourceValidator()
                    .validate(resource, mode, CancelIndicator.NullImpl);
            for (Issue issue : issues) {
                Diagnostic.Severity severity = switch (issue.getSeverity()) {
                    case ERROR -> Diagnostic.Severity.ERROR;
                    case WARNING -> Diagnostic.Severity.WARNING;
                    default -> null;
                };
                if (severity != null) {
                    diagnostics.add(new Diagnostic(displayPath(resource.getURI()), number(issue.getLineNumber()),
                            number(issue.getColumn()), number(issue.getLineNumberEnd()), number(issue.getColumnEnd()),
                            severity, issue.getCode(), issue.getData() == null ? List.of() : List.of(issue.getData()),
                            issue.getMessage()));
                }
            }
        }
        return new ArrayList<>(diagnostics);
    }

    /** A problem found by a generator, positioned at the model element it is about. */
    public Diagnostic error(EObject element, String message) {
        return error(element, null, message);
    }

    /** A problem found by a generator with its issue code (null: none), at the model element it is about. */
    public Diagnostic error(EObject element, String code, String message) {
        Resource resource = element == null ? null : element.eResource();
        String file = resource == null ? "?" : displayPath(resource.getURI());
        ICompositeNode node = NodeModelUtils.findActualNodeFor(element);
        if (node == null) {
            return new Diagnostic(file, 0, 0, 0, 0, Diagnostic.Severity.ERROR, code, List.of(), message);
        }
        LineAndColumn position = NodeModelUtils.getLineAndColumn(node, node.getOffset());
        return new Diagnostic(file, position.getLine(), position.getColumn(), 0, 0, Diagnostic.Severity.ERROR, code,
                List.of(), message);
    }

    private static int number(Integer value) {
        return value == null ? 0 : value;
    }

    /** A file's path as the user sees it: relative to the base folder when inside it. */
    public String displayPath(URI uri) {
        Path path = Path.of(uri.toFileString());
        return path.startsWith(baseDir) ? baseDir.relativize(path).toString() : path.toString();
    }

    /** The files of every resource loaded so far (the given ones and all they import). */
    public List<File> loadedFiles() {
        List<File> files = new ArrayList<>();
        for (Resource resource : resourceSet.getResources()) {
            if (resource.getURI().isFile()) {
                files.add(new File(resource.getURI().toFileString()));
            }
        }
        return files;
    }
}
