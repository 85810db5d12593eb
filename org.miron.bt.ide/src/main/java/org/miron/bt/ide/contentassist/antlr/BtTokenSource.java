package org.miron.bt.ide.contentassist.antlr;

import org.antlr.runtime.TokenSource;

/**
 * The content-assist parser's token source: Xtext's generated code looks for it in this package,
 * and it does what the runtime's does (passes the tokens through unchanged).
 */
public class BtTokenSource extends org.miron.bt.parser.antlr.BtTokenSource {
    public BtTokenSource(TokenSource delegate) {
        super(delegate);
    }
}
