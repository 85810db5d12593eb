package org.miron.runtime.requirement;

/** A requirement's verdict over a run, or so far. */
public enum Verdict {
    HOLDS("holds"),
    /** No violation, but an obligation still open when the run ended (weak end semantics). */
    OPEN("open at the end"),
    VIOLATED("violated"),
    /** A signal it reads never had a value: nothing could be checked. */
    NOT_EVALUATED("never evaluated");

    private final String text;

    Verdict(String text) {
        this.text = text;
    }

    public String text() {
        return text;
    }

    /** As JSON writes it: {@code holds}, {@code open}, {@code violated}, {@code not-evaluated}. */
    public String id() {
        return this == NOT_EVALUATED ? "not-evaluated" : name().toLowerCase(java.util.Locale.ROOT);
    }
}
