package org.miron.bt.ide.contentassist.antlr;

import org.antlr.runtime.CharStream;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.RecognizerSharedState;
import org.miron.bt.ide.contentassist.antlr.lexer.InternalBtLexer;
import org.miron.bt.parser.NodesModelScanner;

/**
 * The generated content-assist lexer with the runtime lexer's hand-written token, so completion
 * sees a {@code <TreeNodesModel>} element as one token, as the parser does.
 */
public class BtContentAssistLexer extends InternalBtLexer {

    public BtContentAssistLexer() {
    }

    public BtContentAssistLexer(CharStream input) {
        super(input);
    }

    public BtContentAssistLexer(CharStream input, RecognizerSharedState state) {
        super(input, state);
    }

    @Override
    public void mTokens() throws RecognitionException {
        if (!NodesModelScanner.scan(input, state, RULE_NODES_MODEL)) {
            super.mTokens();
        }
    }
}
