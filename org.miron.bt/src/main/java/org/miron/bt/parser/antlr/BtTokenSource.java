package org.miron.bt.parser.antlr;

import org.antlr.runtime.Token;
import org.antlr.runtime.TokenSource;

/**
 * Passes the lexer's tokens to the parser unchanged. Xtext wraps the lexer of any grammar with a
 * synthetic token in this class, expecting an indentation-aware language; in the BT grammar the
 * synthetic token is the opaque TreeNodesModel element that {@link org.miron.bt.parser.BtLexer}
 * emits, so there is nothing to split or insert.
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
