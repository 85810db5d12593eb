package org.miron.bt.parser;

import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.miron.bt.validation.BtIssueCodes;

/** Xtext's parser and value-converter messages, under the BT language's own issue code. */
public class BtSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
        return recode(super.getSyntaxErrorMessage(context));
    }

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IValueConverterErrorContext context) {
        return recode(super.getSyntaxErrorMessage(context));
    }

    /**
     * Keeps a ranged message as it is: Xtext recognises it by its code to mark only part of the
     * token (not used by the BT value converters today).
     */
    static SyntaxErrorMessage recode(SyntaxErrorMessage message) {
        if (Diagnostic.SYNTAX_DIAGNOSTIC_WITH_RANGE.equals(message.getIssueCode())) {
            return message;
        }
        return new SyntaxErrorMessage(message.getMessage(), BtIssueCodes.SYNTAX_ERROR, message.getIssueData());
    }
}
