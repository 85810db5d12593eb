package org.miron.bt.parser;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.miron.bt.validation.BtIssueCodes;

/** Xtext's parser and value-converter messages, under the BT language's own issue code. */
public class BtSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

    private static final Pattern MISMATCH = Pattern.compile("mismatched input '([^']+)' expecting '(\\w+)'");

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
        SyntaxErrorMessage message = super.getSyntaxErrorMessage(context);
        SyntaxErrorMessage closing = closingTag(context, message);
        return closing != null ? closing : recode(message);
    }

    /**
     * A built-in closed by another name ({@code <RetryUntilSuccessful> ... </Retry>}): the grammar
     * closes each built-in with its own keyword, so the parser only said "mismatched input". Said
     * as for custom nodes, with the same issue code and data, so the same quick fix applies.
     */
    private static SyntaxErrorMessage closingTag(IParserErrorContext context, SyntaxErrorMessage message) {
        Matcher mismatch = MISMATCH.matcher(message.getMessage());
        RecognitionException exception = context.getRecognitionException();
        if (!mismatch.matches() || exception == null || !(exception.input instanceof TokenStream tokens)
                || !mismatch.group(1).matches("[\\w.:-]+")) {
            return null;
        }
        for (int i = exception.index - 1; i >= 0; i--) {
            Token previous = tokens.get(i);
            if (previous.getChannel() != Token.DEFAULT_CHANNEL) {
                continue;
            }
            if (!"</".equals(previous.getText())) {
                return null;
            }
            String expected = mismatch.group(2);
            String found = mismatch.group(1);
            if (openAbove(tokens, i, expected, found)) {
                // </BehaviorTree> after an unclosed <Sequence>: the Sequence's close tag is missing.
                return new SyntaxErrorMessage("<" + expected + "> is not closed: write </" + expected + "> before </"
                        + found + ">", BtIssueCodes.UNCLOSED_ELEMENT, new String[] { expected });
            }
            return new SyntaxErrorMessage("</" + found + "> does not close <" + expected + ">: write </"
                    + expected + ">", BtIssueCodes.CLOSE_TAG_MISMATCH, new String[] { expected });
        }
        return null;
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

    /**
     * Whether the element the wrong close tag names is open around the one it should close: the
     * elements still open before the tokens' index, innermost last, hold it below the expected one.
     */
    private static boolean openAbove(TokenStream tokens, int end, String expected, String found) {
        java.util.Deque<String> open = new java.util.ArrayDeque<>();
        String previous = null;
        for (int i = 0; i < end; i++) {
            Token token = tokens.get(i);
            if (token.getChannel() != Token.DEFAULT_CHANNEL) {
                continue;
            }
            String text = token.getText();
            if ("<".equals(previous)) {
                open.push(text);
            } else if ("</".equals(previous) && open.contains(text)) {
                while (!open.isEmpty() && !open.pop().equals(text)) {
                    // elements left open inside it end with it
                }
            } else if ("/>".equals(text) && !open.isEmpty()) {
                open.pop();
            }
            previous = text;
        }
        return !open.isEmpty() && open.peek().equals(expected) && open.stream().skip(1).anyMatch(found::equals);
    }
}
