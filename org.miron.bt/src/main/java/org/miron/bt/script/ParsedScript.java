package org.miron.bt.script;

import java.util.List;

import org.miron.bt.script.ast.Script;

/** The result of {@link BtScripts#parse}: the AST (partial when there are errors) and the syntax errors. */
public final class ParsedScript {
    private final String text;
    private final Script script;
    private final List<ScriptSyntaxError> errors;

    ParsedScript(String text, Script script, List<ScriptSyntaxError> errors) {
        this.text = text;
        this.script = script;
        this.errors = List.copyOf(errors);
    }

    /** The parsed text. */
    public String getText() {
        return text;
    }

    /** The syntax tree; never null (an empty Script for empty text), incomplete when {@link #hasErrors()}. */
    public Script getScript() {
        return script;
    }

    public List<ScriptSyntaxError> getErrors() {
        return errors;
    }

    public boolean hasErrors() {
        return !errors.isEmpty();
    }
}
