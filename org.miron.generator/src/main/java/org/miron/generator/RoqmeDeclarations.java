package org.miron.generator;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.util.LineAndColumn;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.Sentence;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.util.Imports;

/**
 * The RoQME declarations a runtime model holds: those of a file and of every RoQME or MIRoN file
 * it imports, transitively (each file once; an import's declarations before the importer's), with
 * their ids. An id is the plain name, or namespace.name when two declarations share a name.
 * Variation points and rules are MIRoN's, not the provider's: they are left out.
 */
final class RoqmeDeclarations {

    /** Every collected declaration (variables, then observations per file) in declaration order. */
    final List<EObject> all = new ArrayList<>();
    private final Map<EObject, String> ids = new HashMap<>();

    private RoqmeDeclarations() {
    }

    /** The declarations of root and its imports; name clashes that ids cannot tell apart go to errors. */
    static RoqmeDeclarations of(RoqmeModel root, List<GenerationError> errors) {
        RoqmeDeclarations d = new RoqmeDeclarations();
        d.collect(root, new HashSet<>());
        d.assignIds(errors);
        return d;
    }

    private void collect(RoqmeModel model, Set<Resource> visited) {
        if (!visited.add(model.eResource())) {
            return;
        }
        for (Import imp : model.getImports()) {
            Resource imported = Imports.load(imp);
            if (imported != null && imported.getContents().get(0) instanceof RoqmeModel importedModel) {
                collect(importedModel, visited);
            }
        }
        for (Variable v : model.getVariables()) {
            if (!(v instanceof VariationPoint)) {
                all.add(v);
            }
        }
        for (Sentence s : model.getSentences()) {
            if (s instanceof Observation) {
                all.add(s);
            }
        }
    }

    private void assignIds(List<GenerationError> errors) {
        Map<String, Integer> uses = new HashMap<>();
        all.forEach(e -> uses.merge(name(e), 1, Integer::sum));
        Map<String, EObject> taken = new LinkedHashMap<>();
        for (EObject e : all) {
            String name = name(e);
            String ns = namespace(e);
            String id = uses.get(name) > 1 && ns != null ? ns + "." + name : name;
            EObject other = taken.putIfAbsent(id, e);
            if (other != null) {
                errors.add(new GenerationError(e, "'" + name + "' is declared twice (also at " + at(other)
                        + ") and no namespace tells them apart in the runtime model: rename one or give the files "
                        + "different `roqme NAME` headers", RoqmeRuntimeModel.NAME_CLASH));
            }
            ids.put(e, id);
        }
    }

    /** The id of a collected declaration, or null when it is not part of the runtime model. */
    String id(EObject declaration) {
        return declaration == null ? null : ids.get(declaration);
    }

    static String name(EObject declaration) {
        return declaration instanceof Variable v ? v.getName() : ((Observation) declaration).getName();
    }

    /** The `roqme X` / `miron X` header name of the declaring file, or null. */
    static String namespace(EObject declaration) {
        EObject root = declaration.eResource() == null ? null : declaration.eResource().getContents().get(0);
        String ns = root instanceof RoqmeModel model ? model.getNamespace() : null;
        return ns == null || ns.isEmpty() ? null : ns;
    }

    /** "file:line:col" of a declaration's name. */
    static String at(EObject declaration) {
        EStructuralFeature feature = declaration instanceof Variable ? RoqmePackage.Literals.VARIABLE__NAME
                : RoqmePackage.Literals.OBSERVATION__NAME;
        List<INode> nodes = NodeModelUtils.findNodesForFeature(declaration, feature);
        INode node = nodes.isEmpty() ? NodeModelUtils.findActualNodeFor(declaration) : nodes.get(0);
        String file = declaration.eResource().getURI().lastSegment();
        if (node == null) {
            return file + ":0:0";
        }
        LineAndColumn position = NodeModelUtils.getLineAndColumn(node, node.getOffset());
        return file + ":" + position.getLine() + ":" + position.getColumn();
    }
}
