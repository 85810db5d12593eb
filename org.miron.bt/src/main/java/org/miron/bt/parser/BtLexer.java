package org.miron.bt.parser;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.RecognizerSharedState;
import org.miron.bt.parser.antlr.lexer.InternalBtLexer;

/**
 * The generated lexer plus one hand-written token: a whole {@code <TreeNodesModel>} element,
 * kept verbatim as opaque text ({@link NodesModelScanner}).
 */
public class BtLexer extends InternalBtLexer {

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
        if (!NodesModelScanner.scan(input, state, RULE_NODES_MODEL)) {
            super.mTokens();
        }
    }
}
