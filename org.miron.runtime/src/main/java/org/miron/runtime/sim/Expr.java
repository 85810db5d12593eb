package org.miron.runtime.sim;

import java.util.Set;
import org.miron.executor.scripting.ScriptCode;
import org.miron.executor.scripting.ScriptScope;
import org.miron.executor.scripting.ScriptValues;

/**
 * A checked world expression or script (BehaviorTree.CPP 4 script language), compiled once: its
 * source, static type, the names it reads and writes, and the code that runs it on the world's
 * blackboard.
 */
public record Expr(String source, SimType type, Set<String> reads, Set<String> writes, ScriptCode code) {

    public Object run(ScriptScope scope) {
        return code.run(scope);
    }

    public double number(ScriptScope scope) {
        return ScriptValues.toDouble(code.run(scope));
    }

    public boolean bool(ScriptScope scope) {
        return ScriptValues.toBoolean(code.run(scope));
    }

    public String text(ScriptScope scope) {
        return String.valueOf(code.run(scope));
    }
}
