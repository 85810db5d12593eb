package org.miron.bt.ide.contentassist.antlr;

import org.antlr.runtime.Token;
import org.antlr.runtime.TokenSource;

/**
 * Passes the content-assist lexer's tokens to the parser unchanged. Xtext wraps the lexer of a
 * grammar with a synthetic token in this class, expecting an indentation-aware language; in the
 * BT grammar the synthetic token is the opaque TreeNodesModel element, so there is nothing to
 * split or insert (as in the runtime's org.miron.bt.parser.antlr.BtTokenSource).
 */
public class BtTokenSource implements TokenSource {
    private final TokenSource delegate;

    public BtTokenSource(TokenSource delegate) {
        this.delegate = delegate;
    }

    @Override
    public Token nextToken() {
        return delegate.nextToken();
    }

    @Override
    public String getSourceName() {
        return delegate.getSourceName();
    }
}
