package org.miron.dsl.linking;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.util.Suggestions;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.scoping.RoqmeScopeProvider;
import org.miron.dsl.util.Imports;
import org.miron.dsl.util.Formulas;
import org.miron.dsl.validation.MironIssueCodes;
import org.miron.dsl.validation.RoqmeIssueCodes;

import com.google.inject.Inject;

/**
 * Unresolved references, named in the user's terms: what kind of element was expected, what the
 * name denotes instead when it exists with another kind, and how imported names are written. Each
 * carries a {@link RoqmeIssueCodes} code and, as issue data, what a quick fix needs: the import to
 * add when a file next to this one declares the name, else the closest visible names ("did you mean").
 */
public class DslLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

    @Inject
    private IScopeProvider scopeProvider;

    @Inject
    private IQualifiedNameConverter nameConverter;

    @Inject
    private MissingImports missingImports;

    @Override
    public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
        EClass type = context.getReference().getEReferenceType();
        String text = context.getLinkText();
        String kind = otherKind(context.getContext(), text);
        if (kind != null && type == BtPackage.Literals.BEHAVIOR_TREE && kind.equals(describe(BtPackage.Literals.TREE_NODE))) {
            // Trees and named nodes share the alias's names: after a tree is renamed its old name often
            // denotes a node (<Sequence name="Charge">), which is no news to the user. Say which trees there are.
            return new DiagnosticMessage("unknown behavior tree '" + text + "': no BehaviorTree has this ID"
                    + trees(context), Severity.ERROR, RoqmeIssueCodes.UNKNOWN_REFERENCE, closest(context, "."));
        }
        if (kind != null) {
            return new DiagnosticMessage("unknown " + describe(type) + " '" + text + "': it is " + article(kind)
                    + ", not " + article(describe(type)), Severity.ERROR, RoqmeIssueCodes.WRONG_KIND_REFERENCE);
        }
        String message = "unknown " + describe(type) + " '" + text + "'" + hint(context.getContext(), type, text);
        String delimiter = text.contains("::") ? "::" : ".";
        MissingImports.Fix fix = missingImports.find(context.getContext(), context.getReference(),
                nameConverter.toQualifiedName(text), delimiter);
        if (fix != null) {
            return new DiagnosticMessage(message, Severity.ERROR, RoqmeIssueCodes.MISSING_IMPORT, fix.importLine(),
                    fix.reference());
        }
        // inside a requirement the name is one the monitor cannot read: its own code (docs/issue-codes.md)
        String code = Formulas.requirementOf(context.getContext()) != null ? MironIssueCodes.REQUIREMENT_UNKNOWN_NAME
                : RoqmeIssueCodes.UNKNOWN_REFERENCE;
        return new DiagnosticMessage(message, Severity.ERROR, code, closest(context, delimiter));
    }

    /** The visible names a reference could take, closest to the text written (for "did you mean"). */
    private String[] closest(ILinkingDiagnosticContext context, String delimiter) {
        List<String> names = new ArrayList<>();
        for (IEObjectDescription d : scopeProvider.getScope(context.getContext(), context.getReference())
                .getAllElements()) {
            names.add(String.join(delimiter, d.getName().getSegments()));
        }
        return Suggestions.closest(context.getLinkText(), names).toArray(new String[0]);
    }

    /** " (the trees are: a.X, a.Y)" for the trees a tree reference can name, or "" if there are none. */
    private String trees(ILinkingDiagnosticContext context) {
        List<String> names = new ArrayList<>();
        for (IEObjectDescription d : scopeProvider.getScope(context.getContext(), context.getReference()).getAllElements()) {
            if (d.getEClass() == BtPackage.Literals.BEHAVIOR_TREE) {
                names.add(String.join(".", d.getName().getSegments()));
            }
        }
        if (names.isEmpty()) {
            return "";
        }
        List<String> shown = names.size() > 12 ? names.subList(0, 12) : names;
        return " (the trees are: " + String.join(", ", shown) + (names.size() > shown.size() ? ", ..." : "") + ")";
    }

    /** What the name denotes when it exists, but as an element of another kind; null otherwise. */
    private String otherKind(EObject context, String text) {
        QualifiedName name = nameConverter.toQualifiedName(text);
        if (scopeProvider instanceof RoqmeScopeProvider) {
            for (IEObjectDescription d : ((RoqmeScopeProvider) scopeProvider).visible(context.eResource())) {
                if (d.getName().equals(name)) {
                    return d.getEClass() == RoqmePackage.Literals.BELIEF_VARIABLE ? "belief" : describe(d.getEClass());
                }
            }
        }
        return null;
    }

    private String hint(EObject context, EClass type, String text) {
        if (type == RoqmePackage.Literals.ENUM_LITERAL) {
            return " (write Type::LITERAL, variable::literal, or alias::Type::LITERAL for an imported one)";
        }
        EObject root = context.eResource() == null || context.eResource().getContents().isEmpty() ? null
                : context.eResource().getContents().get(0);
        String unnamed = type == BtPackage.Literals.BEHAVIOR_TREE ? unnamedTreeIn(root) : null;
        if (unnamed != null) {
            return " (the BehaviorTree without ID in " + unnamed + " cannot be referenced: give it an ID there)";
        }
        if (text.indexOf('.') < 0 && root instanceof RoqmeModel && !((RoqmeModel) root).getImports().isEmpty()) {
            return " (elements of an imported file are written with its alias or namespace: x." + text + ")";
        }
        return "";
    }

    /** The name of an imported BT file holding a tree without ID (BehaviorTree.CPP's tutorial form), or null. */
    private static String unnamedTreeIn(EObject root) {
        if (!(root instanceof RoqmeModel model)) {
            return null;
        }
        for (Import imp : model.getImports()) {
            Resource imported = Imports.load(imp);
            if (imported != null && !imported.getContents().isEmpty()
                    && imported.getContents().get(0) instanceof BTModel bt
                    && bt.getTrees().stream().anyMatch(t -> t.getName() == null || t.getName().isEmpty())) {
                return imported.getURI().lastSegment();
            }
        }
        return null;
    }

    private static String article(String what) {
        return ("aeiou".indexOf(what.charAt(0)) >= 0 ? "an " : "a ") + what;
    }

    private static String describe(EClass type) {
        if (type == BtPackage.Literals.BEHAVIOR_TREE) {
            return "behavior tree";
        } else if (BtPackage.Literals.TREE_NODE.isSuperTypeOf(type)) {
            return "behavior tree node";
        } else if (type == BtPackage.Literals.ATTRIBUTE) {
            return "behavior tree attribute";
        } else if (RoqmePackage.Literals.ENUM_LITERAL.isSuperTypeOf(type)) {
            return "enum literal";
        } else if (type == RoqmePackage.Literals.TYPE_DEFINITION) {
            return "type";
        } else if (type == RoqmePackage.Literals.BELIEF_VARIABLE) {
            return "belief or property";
        } else if (type == RoqmePackage.Literals.PROPERTY) {
            return "property";
        } else if (type == RoqmePackage.Literals.TIMER) {
            return "timer";
        } else if (type == RoqmePackage.Literals.CONTEXT) {
            return "context";
        } else if (type == RoqmePackage.Literals.PARAM) {
            return "param";
        } else if (type == RoqmePackage.Literals.VAR) {
            return "var";
        } else if (type == RoqmePackage.Literals.OBSERVATION) {
            return "observation";
        } else if ("VariationPoint".equals(type.getName())) {
            return "varpoint";
        } else if ("Rule".equals(type.getName())) {
            return "rule";
        } else if ("Requirement".equals(type.getName())) {
            return "requirement";
        }
        return "variable";
    }
}
