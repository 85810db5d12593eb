package org.miron.runtime.requirement;

/**
 * Kleene's three truth values. OPEN is neither true nor false: a window that reaches past the end
 * of the run without a witness (weak end semantics), or a state formula whose signals have no value
 * yet. Only FALSE is ever a violation.
 */
public enum Truth {
    FALSE, TRUE, OPEN;

    static Truth of(boolean b) {
        return b ? TRUE : FALSE;
    }

    Truth not() {
        return this == TRUE ? FALSE : this == FALSE ? TRUE : OPEN;
    }

    Truth and(Truth o) {
        return this == FALSE || o == FALSE ? FALSE : this == TRUE && o == TRUE ? TRUE : OPEN;
    }

    Truth or(Truth o) {
        return this == TRUE || o == TRUE ? TRUE : this == FALSE && o == FALSE ? FALSE : OPEN;
    }
}
