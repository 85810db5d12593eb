package org.miron.dsl.util;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.TypeDefinition;
import org.miron.dsl.roqme.Variable;

/** How elements are named in messages. */
public final class Names {

    private Names() {
    }

    /** The name of the type definition or variable an enumeration belongs to. */
    public static String enumName(EObject enumType) {
        for (EObject c = enumType; c != null; c = c.eContainer()) {
            if (c instanceof TypeDefinition || c instanceof Variable) {
                return DslQualifiedNameProvider.nameOf(c);
            }
        }
        return "?";
    }

    public static String literal(EnumLiteral literal) {
        return enumName(literal.eContainer()) + "::" + literal.getName();
    }
}
