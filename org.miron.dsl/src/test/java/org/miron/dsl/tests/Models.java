package org.miron.dsl.tests;

import java.io.File;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.miron.dsl.MironStandaloneSetup;
import org.miron.testkit.RepositoryRoot;

import com.google.inject.Injector;

/** Loads model files the way the `miron check` CLI does: by extension, with what they import. */
final class Models {

    private static Injector injector;

    private Models() {
    }

    static synchronized Injector injector() {
        if (injector == null) {
            injector = MironStandaloneSetup.doSetup();
        }
        return injector;
    }

    static File root() {
        return RepositoryRoot.path().toFile();
    }

    /** A fresh resource set holding the file and, after resolving, everything it imports. */
    static Resource load(File file) {
        XtextResourceSet set = injector().getInstance(XtextResourceSet.class);
        Resource resource = set.getResource(URI.createFileURI(file.getAbsolutePath()), true);
        EcoreUtil.resolveAll(set);
        return resource;
    }

    /** Issues of every resource in the set (the file and what it imports), as the CLI reports them. */
    static List<Issue> validateAll(Resource resource) {
        List<Issue> issues = new ArrayList<>();
        // validating may load more imports: iterate over a snapshot until nothing new appears
        List<Resource> done = new ArrayList<>();
        boolean more = true;
        while (more) {
            more = false;
            for (Resource r : new ArrayList<>(resource.getResourceSet().getResources())) {
                if (done.contains(r) || !(r instanceof XtextResource)) {
                    continue;
                }
                done.add(r);
                more = true;
                IResourceValidator validator = ((XtextResource) r).getResourceServiceProvider().getResourceValidator();
                for (Issue issue : validator.validate(r, CheckMode.ALL, CancelIndicator.NullImpl)) {
                    // syntax errors come without a URI: say which file they are in
                    if (issue.getUriToProblem() == null && issue instanceof Issue.IssueImpl) {
                        ((Issue.IssueImpl) issue).setUriToProblem(r.getURI());
                    }
                    issues.add(issue);
                }
            }
        }
        return issues;
    }

    /** Cross-references still unresolved after resolving everything. */
    static List<String> unresolved(Resource resource) {
        List<String> result = new ArrayList<>();
        for (Resource r : resource.getResourceSet().getResources()) {
            r.getAllContents().forEachRemaining(obj -> {
                for (EObject target : obj.eCrossReferences()) {
                    if (target.eIsProxy()) {
                        result.add(r.getURI().lastSegment() + ": " + obj.eClass().getName() + " -> " + EcoreUtil.getURI(target));
                    }
                }
            });
        }
        return result;
    }

    static String format(Issue issue) {
        return issue.getUriToProblem().trimFragment().lastSegment() + ":" + issue.getLineNumber() + ":"
                + issue.getColumn() + ": " + issue.getSeverity().name().toLowerCase() + ": " + issue.getMessage();
    }
}
