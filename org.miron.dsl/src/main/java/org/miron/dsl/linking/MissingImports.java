package org.miron.dsl.linking;

import java.io.File;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.IResourceScopeCache;
import org.eclipse.xtext.util.Tuples;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

import com.google.inject.Inject;
import com.google.inject.Provider;

/**
 * Finds the import that would make an unknown name visible: a file in the same folder, not yet
 * imported, that declares the name. {@code b.x} with no import aliased {@code b} is found in a
 * .bt/.roqme/.miron file declaring {@code x} ({@code import "f" as b}, MIRoN only) or in a RoQME
 * file with namespace {@code b}; a plain {@code x} in a file without namespace, or with one (then
 * written {@code Ns.x}). Sibling files are parsed once per state of the importing file, in a
 * resource set of their own, so nothing is added to the one being validated.
 */
public class MissingImports {

    /** The import line to add, and how the reference is written once it is there. */
    public record Fix(String importLine, String reference) {
    }

    /** What a sibling file declares: its local names, and its namespace (empty when none). */
    private record Declarations(QualifiedName namespace, List<IEObjectDescription> names) {
    }

    private static final Declarations NONE = new Declarations(QualifiedName.EMPTY, List.of());

    @Inject
    private IResourceScopeCache cache;

    @Inject
    private Provider<XtextResourceSet> resourceSets;

    /**
     * The import that makes {@code wanted} visible as an element of the reference's type, or null.
     * The reference is written with the delimiter given ("." or "::").
     */
    public Fix find(EObject context, EReference reference, QualifiedName wanted, String delimiter) {
        Resource resource = context.eResource();
        if (resource == null || resource.getURI() == null || !resource.getURI().isFile() || wanted.isEmpty()
                || resource.getContents().isEmpty() || !(resource.getContents().get(0) instanceof RoqmeModel)) {
            return null;
        }
        RoqmeModel model = (RoqmeModel) resource.getContents().get(0);
        Set<URI> imported = new HashSet<>();
        Set<String> aliases = new HashSet<>();
        for (Import imp : model.getImports()) {
            if (Imports.uriOf(imp) != null) {
                imported.add(Imports.uriOf(imp));
            }
            if (Imports.aliasOf(imp) != null) {
                aliases.add(Imports.aliasOf(imp));
            }
        }
        boolean canAlias = "miron".equals(resource.getURI().fileExtension());
        Map<URI, Declarations> siblings = siblings(resource);
        for (Map.Entry<URI, Declarations> sibling : siblings.entrySet()) {
            if (imported.contains(sibling.getKey())) {
                continue;
            }
            String file = "import \"" + sibling.getKey().lastSegment() + "\"";
            Declarations d = sibling.getValue();
            for (IEObjectDescription name : d.names()) {
                if (!reference.getEReferenceType().isSuperTypeOf(name.getEClass())) {
                    continue;
                }
                QualifiedName local = name.getName();
                if (d.namespace().append(local).equals(wanted)) {
                    return new Fix(file, write(wanted, delimiter));
                }
                if (wanted.getSegmentCount() > 1 && canAlias && !aliases.contains(wanted.getFirstSegment())
                        && local.equals(wanted.skipFirst(1))) {
                    return new Fix(file + " as " + wanted.getFirstSegment(), write(wanted, delimiter));
                }
                if (!d.namespace().isEmpty() && local.equals(wanted)) {
                    return new Fix(file, write(d.namespace().append(local), delimiter));
                }
            }
        }
        return null;
    }

    private static String write(QualifiedName name, String delimiter) {
        return String.join(delimiter, name.getSegments());
    }

    /** The importable files next to a resource and what they declare, sorted by name. */
    private Map<URI, Declarations> siblings(Resource resource) {
        return cache.get(Tuples.pair(MissingImports.class, "siblings"), resource, () -> {
            Map<URI, Declarations> result = new LinkedHashMap<>();
            File folder = new File(resource.getURI().toFileString()).getParentFile();
            File[] files = folder == null ? null : folder.listFiles();
            if (files == null) {
                return result;
            }
            Set<String> importable = "miron".equals(resource.getURI().fileExtension())
                    ? Set.of("bt", "roqme", "miron") : Set.of("roqme");
            Arrays.sort(files);
            XtextResourceSet set = resourceSets.get();
            for (File f : files) {
                URI uri = URI.createFileURI(f.getAbsolutePath());
                if (f.isFile() && importable.contains(uri.fileExtension()) && !uri.equals(resource.getURI())) {
                    result.put(uri, declarations(set, uri));
                }
            }
            return result;
        });
    }

    private static Declarations declarations(XtextResourceSet set, URI uri) {
        try {
            Resource sibling = set.getResource(uri, true);
            IResourceServiceProvider provider = IResourceServiceProvider.Registry.INSTANCE
                    .getResourceServiceProvider(uri);
            if (sibling == null || provider == null || sibling.getContents().isEmpty()) {
                return NONE;
            }
            EObject root = sibling.getContents().get(0);
            QualifiedName namespace = root instanceof RoqmeModel && ((RoqmeModel) root).getNamespace() != null
                    ? QualifiedName.create(((RoqmeModel) root).getNamespace().split("\\.")) : QualifiedName.EMPTY;
            List<IEObjectDescription> names = new ArrayList<>();
            provider.getResourceDescriptionManager().getResourceDescription(sibling).getExportedObjects()
                    .forEach(names::add);
            return new Declarations(namespace, names);
        } catch (RuntimeException e) {
            // an unreadable sibling offers no import; it is not the file being checked
            return NONE;
        }
    }
}
