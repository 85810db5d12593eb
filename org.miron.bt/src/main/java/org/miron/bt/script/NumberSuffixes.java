package org.miron.bt.script;

import java.util.List;

import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.miron.bt.script.ast.NumberLiteral;

/**
 * BT.CPP rejects a number directly followed by '.', a letter or '_' ({@code 1..2}, {@code 1.5.2},
 * {@code 12abc}: "invalid suffix"), which a maximal-munch lexer would split into valid tokens.
 */
final class NumberSuffixes {
    private NumberSuffixes() {
    }

    static void check(INode root, String text, List<ScriptSyntaxError> errors) {
        for (ILeafNode leaf : root.getLeafNodes()) {
            if (!(leaf.getSemanticElement() instanceof NumberLiteral) || leaf.isHidden() || leaf.getLength() == 0) {
                continue;
            }
            int end = leaf.getEndOffset();
            if (end < text.length()) {
                char next = text.charAt(end);
                if (next == '.' || next == '_' || Character.isLetter(next)) {
                    errors.add(new ScriptSyntaxError(end, 1, "invalid suffix on number literal"));
                }
            }
        }
    }
}
