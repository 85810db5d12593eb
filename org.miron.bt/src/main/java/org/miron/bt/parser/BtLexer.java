package org.miron.bt.parser;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.RecognizerSharedState;
import org.antlr.runtime.Token;
import org.miron.bt.parser.antlr.lexer.InternalBtLexer;

/**
 * The generated lexer plus one hand-written token: a whole {@code <TreeNodesModel>} element,
 * kept verbatim as opaque text. ANTLR 3's lexer prediction commits after {@code <T} and so cannot
 * have both '<TreeNodesModel...' and '<' 'Timeout' as rules; here the decision is made by
 * looking ahead as far as needed.
 */
public class BtLexer extends InternalBtLexer {
    private static final String OPEN = "<TreeNodesModel";
    private static final String CLOSE = "</TreeNodesModel";

    public BtLexer() {
    }

    public BtLexer(CharStream input) {
        super(input);
    }

    public BtLexer(CharStream input, RecognizerSharedState state) {
        super(input, state);
    }

    @Override
    public void mTokens() throws RecognitionException {
        if (lookingAt(OPEN) && !isNameChar(input.LA(OPEN.length() + 1))) {
            matchNodesModel();
        } else {
            super.mTokens();
        }
    }

    /** Consumes the element up to its end: '/>' of the start tag, or the matching end tag. */
    private void matchNodesModel() {
        state.type = RULE_NODES_MODEL;
        state.channel = Token.DEFAULT_CHANNEL;
        consume(OPEN.length());
        int depth = 0;
        while (input.LA(1) != CharStream.EOF) {
            if (lookingAt("/>") && depth == 0) {
                consume(2);
                return;
            }
            if (input.LA(1) == '>' && depth == 0) {
                consume(1);
                depth = 1;
            } else if (depth > 0 && lookingAt(CLOSE) && !isNameChar(input.LA(CLOSE.length() + 1))) {
                consume(CLOSE.length());
                while (input.LA(1) != CharStream.EOF && input.LA(1) != '>') {
                    consume(1);
                }
                consume(1);
                return;
            } else {
                consume(1);
            }
        }
        // Unterminated: the token runs to the end of the file and the parser reports what is missing.
    }

    private boolean lookingAt(String text) {
        for (int i = 0; i < text.length(); i++) {
            if (input.LA(i + 1) != text.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    private void consume(int count) {
        for (int i = 0; i < count && input.LA(1) != CharStream.EOF; i++) {
            input.consume();
        }
    }

    private static boolean isNameChar(int c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '-' || c == '.' || c == ':';
    }
}
