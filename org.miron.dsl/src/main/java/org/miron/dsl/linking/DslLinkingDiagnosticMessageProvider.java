package org.miron.dsl.linking;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.miron.bt.bt.BtPackage;
import org.miron.dsl.roqme.RoqmePackage;

/** Unresolved references, named in the user's terms and with a hint on how names are written. */
public class DslLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

    @Override
    public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
        EClass type = context.getReference().getEReferenceType();
        String what = describe(type);
        String hint = "";
        if (type == RoqmePackage.Literals.ENUM_LITERAL) {
            hint = " (write Type::LITERAL, variable::literal, or alias::Type::LITERAL for an imported one)";
        } else if (context.getLinkText().indexOf('.') < 0) {
            hint = " (elements of an imported file are written alias.name)";
        }
        return new DiagnosticMessage("unknown " + what + " '" + context.getLinkText() + "'" + hint,
                Severity.ERROR, Diagnostic.LINKING_DIAGNOSTIC);
    }

    private static String describe(EClass type) {
        if (type == BtPackage.Literals.BEHAVIOR_TREE) {
            return "behavior tree";
        } else if (type == BtPackage.Literals.TREE_NODE) {
            return "behavior tree node";
        } else if (type == RoqmePackage.Literals.ENUM_LITERAL) {
            return "enum literal";
        } else if (type == RoqmePackage.Literals.TYPE_DEFINITION) {
            return "type";
        } else if (type == RoqmePackage.Literals.BELIEF_VARIABLE) {
            return "belief or property";
        } else if (type == RoqmePackage.Literals.PROPERTY) {
            return "property";
        } else if (type == RoqmePackage.Literals.TIMER) {
            return "timer";
        }
        return "variable";
    }
}
