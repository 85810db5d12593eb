package org.miron.dsl.util;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.roqme.EnumLiteral;

/** How elements are named in messages. */
public final class Names {

    private Names() {
    }

    /** The name of the type definition or variable an enumeration belongs to. */
    public static String enumName(EObject enumType) {
        return ownerName(enumType);
    }

    /** The name of the type definition or variable (or other named element) that contains an element. */
    public static String ownerName(EObject element) {
        for (EObject c = element; c != null; c = c.eContainer()) {
            String name = DslQualifiedNameProvider.nameOf(c);
            if (name != null) {
                return name;
            }
        }
        return "?";
    }

    public static String literal(EnumLiteral literal) {
        return enumName(literal.eContainer()) + "::" + literal.getName();
    }
}
