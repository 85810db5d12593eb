package org.miron.runtime.sim;

import java.util.ArrayList;
import java.util.List;

/** Problems found in a world file, placed by JSON pointer (and character of an expression) at line:col. */
final class Diagnostics {
    private final String file;
    private final PositionedJson json;
    private final List<String> lines = new ArrayList<>();

    Diagnostics(String file, PositionedJson json) {
        this.file = file;
        this.json = json;
    }

    void error(String pointer, String code, String message) {
        at(pointer, -1, code, message);
    }

    /** A problem with the name of the member at {@code pointer} (an unknown skill, context...). */
    void name(String pointer, String code, String message) {
        add(json.keyAt(pointer), pointer, code, message);
    }

    /** {@code offset}: a character of the string value at {@code pointer} (-1: the value itself). */
    void at(String pointer, int offset, String code, String message) {
        PositionedJson.Position p = json.at(pointer);
        int column = offset < 0 ? p.column() : p.column() + 1 + offset; // after the opening quote
        add(new PositionedJson.Position(p.line(), column), pointer, code, message);
    }

    private void add(PositionedJson.Position p, String pointer, String code, String message) {
        int column = p.column();
        lines.add(file + ":" + p.line() + ":" + column + ": error [world." + code + "]: " + message + " (at "
                + (pointer.isEmpty() ? "/" : pointer) + ")");
    }

    boolean any() {
        return !lines.isEmpty();
    }

    List<String> lines() {
        return lines;
    }
}
