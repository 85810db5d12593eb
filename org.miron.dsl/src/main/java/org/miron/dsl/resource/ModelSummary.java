package org.miron.dsl.resource;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.EObjectDescription;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.util.Imports;

/**
 * The index entry of a RoQME/MIRoN model root: its namespace and the URIs it imports, as user
 * data. It lets importers find the namespace prefix, and the builder find who imports what,
 * from the index alone, without loading any file. The name cannot be written in either language,
 * and no reference targets a model root, so the entry never shows in a scope.
 */
public final class ModelSummary {

    public static final QualifiedName NAME = QualifiedName.create("$model");

    private static final String NAMESPACE = "namespace";
    private static final String IMPORTS = "imports";
    // no usable import path contains a line break
    private static final String SEPARATOR = "\n";

    private ModelSummary() {
    }

    public static IEObjectDescription describe(RoqmeModel model) {
        Map<String, String> data = new HashMap<>();
        if (model.getNamespace() != null) {
            data.put(NAMESPACE, model.getNamespace());
        }
        List<String> uris = new ArrayList<>();
        for (Import imp : model.getImports()) {
            URI uri = Imports.uriOf(imp);
            if (uri != null) {
                uris.add(uri.toString());
            }
        }
        data.put(IMPORTS, String.join(SEPARATOR, uris));
        return EObjectDescription.create(NAME, model, data);
    }

    /** The namespace of the described model, or null (none, or not a RoQME/MIRoN file). */
    public static String namespace(IResourceDescription description) {
        IEObjectDescription summary = find(description);
        return summary == null ? null : summary.getUserData(NAMESPACE);
    }

    /** The absolute URIs the described model imports (empty for other files). */
    public static List<URI> imports(IResourceDescription description) {
        IEObjectDescription summary = find(description);
        String text = summary == null ? null : summary.getUserData(IMPORTS);
        List<URI> result = new ArrayList<>();
        if (text != null && !text.isEmpty()) {
            for (String uri : text.split(SEPARATOR)) {
                result.add(URI.createURI(uri));
            }
        }
        return result;
    }

    public static boolean isSummary(IEObjectDescription description) {
        return NAME.equals(description.getName());
    }

    private static IEObjectDescription find(IResourceDescription description) {
        if (description == null) {
            return null;
        }
        for (IEObjectDescription d : description.getExportedObjects(RoqmePackage.Literals.ROQME_MODEL, NAME, false)) {
            return d;
        }
        return null;
    }
}
