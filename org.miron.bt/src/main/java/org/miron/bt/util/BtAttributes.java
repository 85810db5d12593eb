package org.miron.bt.util;

import java.util.List;

import org.miron.bt.bt.Attribute;

/** Lookup of XML attributes, which the metamodel keeps as an ordered list to round-trip files. */
public final class BtAttributes {
    private BtAttributes() {
    }

    /** The value of the first attribute called {@code name}, or null. */
    public static String value(List<Attribute> attributes, String name) {
        for (Attribute attribute : attributes) {
            if (name.equals(attribute.getName())) {
                return attribute.getValue();
            }
        }
        return null;
    }

    /** The attribute called {@code name}, or null. */
    public static Attribute find(List<Attribute> attributes, String name) {
        for (Attribute attribute : attributes) {
            if (name.equals(attribute.getName())) {
                return attribute;
            }
        }
        return null;
    }
}
