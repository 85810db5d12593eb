package org.miron.dds.types;

import java.util.ArrayList;
import java.util.List;

/** The tokens of an .idl file with their positions: identifiers, numbers, strings, punctuation; comments and #-lines dropped. */
final class IdlTokens {
    record Token(String text, int line, int column) {
    }

    private final String file;
    private final List<Token> tokens = new ArrayList<>();
    private final Token end;
    private int at;

    IdlTokens(String file, String text) {
        this.file = file;
        int line = 1;
        int col = 1;
        int i = 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            int len;
            if (c == '\n') {
                line++;
                col = 1;
                i++;
                continue;
            }
            if (Character.isWhitespace(c)) {
                len = 1;
            } else if (c == '#' && col == 1 || text.startsWith("//", i)) {
                len = lineEnd(text, i) - i;
            } else if (text.startsWith("/*", i)) {
                int close = text.indexOf("*/", i + 2);
                int stop = close < 0 ? text.length() : close + 2;
                for (int k = i; k < stop; k++) {
                    if (text.charAt(k) == '\n') {
                        line++;
                        col = 0;
                    }
                    col++;
                }
                i = stop;
                continue;
            } else {
                if (Character.isLetterOrDigit(c) || c == '_' || c == '-' && i + 1 < text.length() && Character.isDigit(text.charAt(i + 1))
                        || c == '.' && i + 1 < text.length() && Character.isDigit(text.charAt(i + 1))) {
                    len = 1;
                    while (i + len < text.length() && (Character.isLetterOrDigit(text.charAt(i + len)) || "_.+-".indexOf(text.charAt(i + len)) >= 0
                            && (text.charAt(i + len) != '-' && text.charAt(i + len) != '+' || "eE".indexOf(text.charAt(i + len - 1)) >= 0))) {
                        len++;
                    }
                } else if (c == '"') {
                    len = 1;
                    while (i + len < text.length() && text.charAt(i + len) != '"' && text.charAt(i + len) != '\n') {
                        len += text.charAt(i + len) == '\\' ? 2 : 1;
                    }
                    len = Math.min(len + 1, text.length() - i);
                } else if (text.startsWith("::", i)) {
                    len = 2;
                } else {
                    len = 1;
                }
                tokens.add(new Token(text.substring(i, i + len), line, col));
            }
            i += len;
            col += len;
        }
        end = new Token("end of file", line, col);
    }

    private static int lineEnd(String text, int i) {
        int n = text.indexOf('\n', i);
        return n < 0 ? text.length() : n;
    }

    boolean atEnd() {
        return at >= tokens.size();
    }

    Token peek() {
        return atEnd() ? end : tokens.get(at);
    }

    boolean peekIs(String s) {
        return !atEnd() && tokens.get(at).text().equals(s);
    }

    Token next() throws DefinitionException {
        if (atEnd()) {
            throw error(end, "unexpected end of file");
        }
        return tokens.get(at++);
    }

    void expect(String s) throws DefinitionException {
        Token t = peek();
        if (!t.text().equals(s)) {
            throw error(t, "expected " + s + ", found " + t.text());
        }
        at++;
    }

    Token identifier() throws DefinitionException {
        Token t = peek();
        if (atEnd() || !t.text().matches("[A-Za-z_][A-Za-z0-9_]*")) {
            throw error(t, "a name expected, found " + t.text());
        }
        at++;
        return t;
    }

    int integer() throws DefinitionException {
        Token t = peek();
        if (atEnd() || !t.text().matches("[0-9]{1,9}")) {
            throw error(t, "a non-negative integer expected, found " + t.text());
        }
        at++;
        return Integer.parseInt(t.text());
    }

    /** {@code (value=X)} or {@code (X)} of an annotation: X's text (a string unquoted later), skipping other keys. */
    String annotationValue() throws DefinitionException {
        expect("(");
        StringBuilder value = new StringBuilder();
        int depth = 1;
        boolean inValue = true;
        while (true) {
            Token t = next();
            if (t.text().equals("(")) {
                depth++;
            } else if (t.text().equals(")") && --depth == 0) {
                return value.toString().trim();
            }
            if (depth == 1 && peekIs("=") && t.text().matches("[A-Za-z_]+")) {
                inValue = t.text().equals("value");
                next();
                continue;
            }
            if (depth == 1 && t.text().equals(",")) {
                continue;
            }
            if (inValue) {
                value.append(t.text());
            }
        }
    }

    DefinitionException error(Token t, String why) {
        return new DefinitionException(file, t.line(), t.column(), why);
    }
}
