package org.miron.dsl.naming;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.naming.IQualifiedNameProvider;
import org.eclipse.xtext.naming.QualifiedName;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.TypeDefinition;
import org.miron.dsl.roqme.Variable;

/**
 * Names of RoQME and MIRoN elements inside their own file: variables, types, observations and
 * rules by their name, enum literals as owner::literal where the owner is the type definition or
 * the variable declaring the enum inline. The import alias or the file's namespace is added by
 * the scope provider of the importing file, so names are exported unqualified here.
 */
public class DslQualifiedNameProvider extends IQualifiedNameProvider.AbstractImpl {

    @Override
    public QualifiedName getFullyQualifiedName(EObject obj) {
        if (obj instanceof EnumLiteral) {
            String owner = ownerName(obj.eContainer());
            String name = ((EnumLiteral) obj).getName();
            return owner == null || name == null ? null : QualifiedName.create(owner, name);
        }
        return simple(nameOf(obj));
    }

    /** The name under which a top-level element is known, or null for anything else. */
    public static String nameOf(EObject obj) {
        if (obj instanceof Variable) {
            return ((Variable) obj).getName();
        } else if (obj instanceof TypeDefinition) {
            return ((TypeDefinition) obj).getName();
        } else if (obj instanceof Observation) {
            return ((Observation) obj).getName();
        } else if (obj instanceof Rule) {
            return ((Rule) obj).getName();
        } else if (obj instanceof org.miron.dsl.miron.Requirement) {
            return ((org.miron.dsl.miron.Requirement) obj).getName();
        }
        return null;
    }

    /** The type definition or variable an enum type belongs to. */
    private static String ownerName(EObject enumType) {
        for (EObject c = enumType; c != null; c = c.eContainer()) {
            if (c instanceof TypeDefinition || c instanceof Variable) {
                return nameOf(c);
            }
        }
        return null;
    }

    private static QualifiedName simple(String name) {
        return name == null || name.isEmpty() ? null : QualifiedName.create(name);
    }
}
