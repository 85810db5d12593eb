package org.miron.dsl.linking;

import java.io.File;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceServiceProvider;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.miron.bt.resource.BtXmlFiles;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.util.Imports;

import com.google.inject.Inject;
import com.google.inject.Provider;
import com.google.inject.Singleton;

/**
 * Finds the import that would make an unknown name visible: a file in the same folder, not yet
 * imported, that declares the name. {@code b.x} with no import aliased {@code b} is found in a
 * .bt/.roqme/.miron file declaring {@code x} ({@code import "f" as b}, MIRoN only) or in a RoQME
 * file with namespace {@code b}; a plain {@code x} in a file without namespace, or with one (then
 * written {@code Ns.x}). Sibling files are read from disk, each parsed in a resource set of its
 * own (nothing is added to the one being validated), and what they declare is remembered per
 * file path, modification time and size, so many models in one folder parse each sibling once.
 */
@Singleton
public class MissingImports {
    /** Files whose declarations are remembered; beyond this the oldest are parsed again if needed. */
    private static final int REMEMBERED = 512;

    /** The import line to add, and how the reference is written once it is there. */
    public record Fix(String importLine, String reference) {
    }

    /** A name a file declares and the kind of element it names. */
    private record Declared(QualifiedName name, EClass type) {
    }

    /** What a sibling file declares: its namespace (empty when none) and its local names. */
    private record Declarations(long modified, long size, QualifiedName namespace, List<Declared> names) {
    }

    private final Map<File, Declarations> remembered = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<File, Declarations> eldest) {
            return size() > REMEMBERED;
        }
    };

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
        boolean miron = "miron".equals(resource.getURI().fileExtension());
        for (File sibling : siblings(resource.getURI(), miron)) {
            URI uri = URI.createFileURI(sibling.getAbsolutePath());
            if (imported.contains(uri)) {
                continue;
            }
            String file = "import \"" + sibling.getName() + "\"";
            Declarations d = declarations(sibling);
            for (Declared declared : d.names()) {
                if (!reference.getEReferenceType().isSuperTypeOf(declared.type())) {
                    continue;
                }
                QualifiedName local = declared.name();
                if (d.namespace().append(local).equals(wanted)) {
                    return new Fix(file, write(wanted, delimiter));
                }
                if (wanted.getSegmentCount() > 1 && miron && !aliases.contains(wanted.getFirstSegment())
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

    /** The importable files next to a file, sorted by name. */
    private static List<File> siblings(URI uri, boolean miron) {
        File self = new File(uri.toFileString());
        File[] files = self.getParentFile() == null ? null : self.getParentFile().listFiles();
        if (files == null) {
            return List.of();
        }
        Set<String> importable = miron ? Set.of("bt", "xml", "roqme", "miron") : Set.of("roqme");
        List<File> result = new ArrayList<>();
        for (File f : files) {
            String name = f.getName();
            String extension = name.substring(name.lastIndexOf('.') + 1);
            if (f.isFile() && importable.contains(extension) && !f.equals(self)
                    && (!extension.equals("xml") || BtXmlFiles.looksLikeBehaviourTree(URI.createFileURI(f.getPath())))) {
                result.add(f);
            }
        }
        result.sort(null);
        return result;
    }

    private synchronized Declarations declarations(File file) {
        Declarations known = remembered.get(file);
        if (known != null && known.modified() == file.lastModified() && known.size() == file.length()) {
            return known;
        }
        Declarations read = read(file);
        remembered.put(file, read);
        return read;
    }

    private Declarations read(File file) {
        long modified = file.lastModified();
        long size = file.length();
        URI uri = URI.createFileURI(file.getAbsolutePath());
        try {
            Resource sibling = resourceSets.get().getResource(uri, true);
            IResourceServiceProvider provider = IResourceServiceProvider.Registry.INSTANCE
                    .getResourceServiceProvider(uri);
            if (sibling == null || provider == null || sibling.getContents().isEmpty()) {
                return new Declarations(modified, size, QualifiedName.EMPTY, List.of());
            }
            EObject root = sibling.getContents().get(0);
            QualifiedName namespace = root instanceof RoqmeModel && ((RoqmeModel) root).getNamespace() != null
                    ? QualifiedName.create(((RoqmeModel) root).getNamespace().split("\\.")) : QualifiedName.EMPTY;
            List<Declared> names = new ArrayList<>();
            for (IEObjectDescription d : provider.getResourceDescriptionManager().getResourceDescription(sibling)
                    .getExportedObjects()) {
                names.add(new Declared(d.getName(), d.getEClass()));
            }
            return new Declarations(modified, size, namespace, names);
        } catch (RuntimeException e) {
            // an unreadable sibling offers no import; it is not the file being checked
            return new Declarations(modified, size, QualifiedName.EMPTY, List.of());
        }
    }
}
