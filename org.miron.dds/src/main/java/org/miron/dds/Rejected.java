package org.miron.dds;

/** A DDS sample or bus message the bridge drops, and why (one log line, one count). */
final class Rejected extends Exception {
    private static final long serialVersionUID = 1L;

    Rejected(String why) {
        super(why, null, false, false);
    }
}
