package org.miron.dsl.parser;

import static org.miron.dsl.validation.RoqmeIssueCodes.SYNTAX_ERROR;

import org.antlr.runtime.FailedPredicateException;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;

/** Rewords the parser messages that would make no sense to a modeller; all carry RoqmeIssueCodes.SYNTAX_ERROR. */
public class DslSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
        if (context.getRecognitionException() instanceof FailedPredicateException) {
            String rule = ((FailedPredicateException) context.getRecognitionException()).ruleName;
            if (rule != null && rule.contains("ArchBinding")) {
                return new SyntaxErrorMessage("an arch binding needs parameterSetRepository, parameterSet, component"
                        + " and parameter, each exactly once (in any order)", SYNTAX_ERROR);
            }
        }
        RecognitionException e = context.getRecognitionException();
        if (e != null && e.token != null && e.token.getText() != null && e.token.getText().startsWith("/**")) {
            // documentation comments are tokens, not hidden: they belong to the next declaration
            return new SyntaxErrorMessage("a documentation comment /** ... */ must come right before a declaration"
                    + " (model header, import, type, context, param, var, timer, beliefvar, property, observation,"
                    + " varpoint or rule); write /* ... */ for other comments", SYNTAX_ERROR);
        }
        if (e != null && e.token != null && e.token.getText() != null && e.token.getText().matches("[0-9.]+")
                && "within".equals(previousText(e))) {
            // the bound's unit is missing or misspelt (within 5 s): without one, within reads as a name
            return new SyntaxErrorMessage("a bound is a number and a time unit: within " + e.token.getText()
                    + " seconds (milliseconds, seconds, minutes, hours or days)", SYNTAX_ERROR);
        }
        String lexer = context.getDefaultMessage();
        if (e == null && lexer != null && lexer.contains("character '<EOF>'")) {
            // the lexer reached the end of the file inside a token: only comments and strings span text
            return new SyntaxErrorMessage(lexer.contains("expecting '\"'")
                    ? "the file ends inside a string: close it with \""
                    : "the file ends inside a comment: close it with */", SYNTAX_ERROR);
        }
        SyntaxErrorMessage message = super.getSyntaxErrorMessage(context);
        String text = readable(message.getMessage(), isKeyword(context));
        if (text != null && text.startsWith("missing EOF at ")) {
            // the parser finished a complete element and cannot start another one here
            return new SyntaxErrorMessage("unexpected " + text.substring("missing EOF at ".length())
                    + ": the element before it is complete and no declaration starts here", SYNTAX_ERROR);
        }
        return new SyntaxErrorMessage(text == null ? message.getMessage() : text, SYNTAX_ERROR, message.getIssueData());
    }

    @Override
    public SyntaxErrorMessage getSyntaxErrorMessage(IValueConverterErrorContext context) {
        SyntaxErrorMessage message = super.getSyntaxErrorMessage(context);
        // a ranged message keeps Xtext's code: Xtext recognises it by that code to mark part of a token
        return Diagnostic.SYNTAX_DIAGNOSTIC_WITH_RANGE.equals(message.getIssueCode()) ? message
                : new SyntaxErrorMessage(message.getMessage(), SYNTAX_ERROR, message.getIssueData());
    }

    /** The text of the visible token before the offending one, or null. */
    private static String previousText(RecognitionException e) {
        if (!(e.input instanceof TokenStream tokens)) {
            return null;
        }
        for (int i = e.token.getTokenIndex() - 1; i >= 0; i--) {
            Token t = tokens.get(i);
            if (t.getChannel() == Token.DEFAULT_CHANNEL) {
                return t.getText();
            }
        }
        return null;
    }

    /** Whether the offending token is a keyword (a word that is not an identifier). */
    private static boolean isKeyword(IParserErrorContext context) {
        RecognitionException e = context.getRecognitionException();
        if (e == null || e.token == null || e.token.getText() == null || !e.token.getText().matches("[A-Za-z_]+")) {
            return false;
        }
        String[] names = context.getTokenNames();
        int type = e.token.getType();
        return names == null || type < 0 || type >= names.length || !"RULE_ID".equals(names[type]);
    }

    /** Token names as a modeller knows them (RULE_ID is "a name"). */
    private static String readable(String text, boolean keyword) {
        if (text == null) {
            return null;
        }
        String result = text.replace("RULE_ID", "a name").replace("RULE_STRING", "a \"string\"")
                .replace("RULE_INT", "an integer").replace("RULE_REAL", "a decimal number")
                .replace("RULE_DOC", "a documentation comment").replace("expecting EOF", "expecting the end of the file");
        if (result.startsWith("no viable alternative at input ")) {
            result = "unexpected " + result.substring("no viable alternative at input ".length())
                    + (keyword ? " (a keyword: it cannot be used as a name)" : "");
        }
        return result;
    }
}
