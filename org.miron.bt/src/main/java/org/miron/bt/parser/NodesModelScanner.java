package org.miron.bt.parser;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.RecognizerSharedState;
import org.antlr.runtime.Token;

/**
 * Recognizes a whole {@code <TreeNodesModel>} element as one opaque token. ANTLR 3's lexer
 * prediction commits after {@code <T} and so cannot have both '<TreeNodesModel...' and '<'
 * 'Timeout' as rules; here the decision is made by looking ahead as far as needed. Shared by the
 * runtime lexer ({@link BtLexer}) and the content-assist lexer of the ide module, which are
 * generated separately but must cut the text into the same tokens.
 */
public final class NodesModelScanner {
    private static final String OPEN = "<TreeNodesModel";
    private static final String CLOSE = "</TreeNodesModel";

    private NodesModelScanner() {
    }

    /**
     * When the input is at a {@code <TreeNodesModel} start tag, consumes the element, sets the
     * token type and returns true; otherwise consumes nothing and returns false.
     */
    public static boolean scan(CharStream input, RecognizerSharedState state, int tokenType) {
        if (!lookingAt(input, OPEN) || isNameChar(input.LA(OPEN.length() + 1))) {
            return false;
        }
        state.type = tokenType;
        state.channel = Token.DEFAULT_CHANNEL;
        consume(input, OPEN.length());
        int depth = 0;
        while (input.LA(1) != CharStream.EOF) {
            if (lookingAt(input, "/>") && depth == 0) {
                consume(input, 2);
                return true;
            }
            if (input.LA(1) == '>' && depth == 0) {
                consume(input, 1);
                depth = 1;
            } else if (depth > 0 && lookingAt(input, CLOSE) && !isNameChar(input.LA(CLOSE.length() + 1))) {
                consume(input, CLOSE.length());
                while (input.LA(1) != CharStream.EOF && input.LA(1) != '>') {
                    consume(input, 1);
                }
                consume(input, 1);
                return true;
            } else {
                consume(input, 1);
            }
        }
        // Unterminated: the token runs to the end of the file and the parser reports what is missing.
        return true;
    }

    private static boolean lookingAt(CharStream input, String text) {
        for (int i = 0; i < text.length(); i++) {
            if (input.LA(i + 1) != text.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    private static void consume(CharStream input, int count) {
        for (int i = 0; i < count && input.LA(1) != CharStream.EOF; i++) {
            input.consume();
        }
    }

    private static boolean isNameChar(int c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '-' || c == '.' || c == ':';
    }
}
