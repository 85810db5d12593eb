package org.miron.runtime.sim;

import java.util.List;

/**
 * The static type of a world value or expression: a number, a boolean, a text (an enum's value or
 * a place name: {@code literals} lists what it may be, null for any text) or, for a skill's inputs
 * (whatever the tree passes), anything.
 */
public record SimType(Kind kind, List<String> literals, String what) {
    public enum Kind { NUMBER, BOOLEAN, TEXT, ANY }

    public static final SimType NUMBER = new SimType(Kind.NUMBER, null, "a number");
    public static final SimType BOOLEAN = new SimType(Kind.BOOLEAN, null, "a boolean");
    public static final SimType TEXT = new SimType(Kind.TEXT, null, "a text");
    public static final SimType ANY = new SimType(Kind.ANY, null, "a skill input");

    public static SimType enumOf(String what, List<String> literals) {
        return new SimType(Kind.TEXT, List.copyOf(literals), what);
    }

    /** Whether a value of type {@code other} may be used where this type is expected. */
    public boolean accepts(SimType other) {
        if (kind == Kind.ANY || other.kind == Kind.ANY) {
            return true;
        }
        if (kind != other.kind) {
            return false;
        }
        return kind != Kind.TEXT || literals == null || other.literals == null || literals.containsAll(other.literals);
    }

    @Override
    public String toString() {
        return what;
    }
}
