package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Map;
import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ParsedScript;
import org.miron.bt.script.ScriptSyntaxError;
import org.miron.executor.scripting.ScriptCompiler;

/** Compiles the expressions of a world file, reporting syntax and type errors at their character. */
final class ExprFactory {
    private final Diagnostics diagnostics;

    ExprFactory(Diagnostics diagnostics) {
        this.diagnostics = diagnostics;
    }

    /**
     * The expression at {@code pointer} ({@code node}: a JSON string, or a number or boolean written
     * as such), null after a problem. {@code expected}: its type (null: any); {@code script}: it may
     * assign state (effects), else it must not.
     */
    Expr compile(JsonNode node, String pointer, Map<String, TypeCheck.Symbol> scope, SimType expected, boolean script) {
        if (node == null || node.isNull()) {
            return null;
        }
        String source;
        if (node.isTextual()) {
            source = node.asText();
        } else if (node.isNumber() || node.isBoolean()) {
            source = node.asText();
        } else {
            diagnostics.error(pointer, "type", "an expression must be a string (BehaviorTree.CPP 4 script)");
            return null;
        }
        ParsedScript parsed = BtScripts.parse(source);
        if (parsed.hasErrors()) {
            ScriptSyntaxError e = parsed.getErrors().get(0);
            diagnostics.at(pointer, node.isTextual() ? e.getOffset() : -1, "syntax", e.getMessage() + " in '" + source + "'");
            return null;
        }
        if (parsed.getScript().getStatements().isEmpty()) {
            diagnostics.error(pointer, "syntax", "empty expression");
            return null;
        }
        TypeCheck check = new TypeCheck(scope);
        SimType type = check.statements(parsed.getScript().getStatements());
        if (!check.problems.isEmpty()) {
            for (TypeCheck.Problem p : check.problems) {
                diagnostics.at(pointer, node.isTextual() ? p.offset() : -1,
                        p.message().startsWith("unknown") ? "unknown-name" : "type", p.message());
            }
            return null;
        }
        if (!script && !check.writes.isEmpty()) {
            diagnostics.error(pointer, "type", "'" + source + "' assigns " + check.writes + ": only effects may change the state");
            return null;
        }
        if (expected != null && type != null && !expected.accepts(type)) {
            diagnostics.error(pointer, "type", "'" + source + "' is " + type + ", " + expected + " is needed here");
            return null;
        }
        try {
            return new Expr(source, type, java.util.Set.copyOf(check.reads), java.util.Set.copyOf(check.writes), ScriptCompiler.compile(source));
        } catch (IllegalArgumentException e) {
            diagnostics.error(pointer, "syntax", e.getMessage());
            return null;
        }
    }

}
