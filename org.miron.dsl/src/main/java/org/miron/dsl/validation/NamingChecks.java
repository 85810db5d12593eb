package org.miron.dsl.validation;

import static org.miron.dsl.validation.RoqmeIssueCodes.*;
import static org.miron.dsl.validation.Texts.line;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.util.Names;

import com.google.inject.Inject;

/** Names: unique in their file, enum literals unique in their enum, references not ambiguous. */
public class NamingChecks extends CheckSet {

    private static final RoqmePackage R = RoqmePackage.eINSTANCE;

    @Inject
    private IScopeProvider scopeProvider;

    @Inject
    private IQualifiedNameConverter nameConverter;

    @Check
    public void checkUniqueNames(RoqmeModel model) {
        Map<String, EObject> seen = new HashMap<>();
        for (EObject obj : model.eContents()) {
            String name = DslQualifiedNameProvider.nameOf(obj);
            if (name == null) {
                continue;
            }
            EObject first = seen.putIfAbsent(name, obj);
            if (first != null) {
                error("duplicate name '" + name + "': already declared at line " + line(first),
                        obj, obj.eClass().getEStructuralFeature("name"), DUPLICATE_NAME, name);
            }
        }
    }

    @Check
    public void checkEnumLiterals(EnumType type) {
        Set<String> seen = new LinkedHashSet<>();
        for (EnumLiteral literal : type.getLiterals()) {
            if (literal.getName() != null && !seen.add(literal.getName())) {
                error("enum literal '" + literal.getName() + "' is repeated in " + Names.enumName(type),
                        literal, R.getEnumLiteral_Name(), DUPLICATE_LITERAL, literal.getName());
            }
        }
    }

    /** Every cross-reference whose name matches several elements (e.g. two imports exposing it). */
    @Check(CheckType.NORMAL)
    public void checkAmbiguousReferences(EObject obj) {
        for (EReference ref : obj.eClass().getEAllReferences()) {
            if (ref.isContainment() || ref.isContainer() || ref.isDerived() || ref.isTransient()) {
                continue;
            }
            List<INode> nodes = NodeModelUtils.findNodesForFeature(obj, ref);
            for (int i = 0; i < nodes.size(); i++) {
                String text = NodeModelUtils.getTokenText(nodes.get(i));
                QualifiedName name = nameConverter.toQualifiedName(text);
                Set<URI> targets = new LinkedHashSet<>();
                for (IEObjectDescription d : scopeProvider.getScope(obj, ref).getElements(name)) {
                    targets.add(d.getEObjectURI());
                }
                if (targets.size() > 1) {
                    StringBuilder where = new StringBuilder();
                    for (URI uri : targets) {
                        where.append(where.length() == 0 ? "" : ", ").append(uri.trimFragment().lastSegment());
                    }
                    error("ambiguous reference '" + text + "': " + targets.size() + " elements have this name (in "
                            + where + "); import one of the files with an alias", obj, ref, ref.isMany() ? i : -1,
                            AMBIGUOUS_REFERENCE);
                }
            }
        }
    }
}
