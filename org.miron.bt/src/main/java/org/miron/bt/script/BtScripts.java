package org.miron.bt.script;

import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.parser.IParseResult;
import org.eclipse.xtext.parser.IParser;
import org.miron.bt.BtScriptStandaloneSetup;
import org.miron.bt.script.ast.AstFactory;
import org.miron.bt.script.ast.Script;

/** Entry point of the scripting language: parses one attribute value (see package-info). */
public final class BtScripts {
    private static IParser parser; // guarded by the class

    private BtScripts() {
    }

    /**
     * Parses a script as BehaviorTree.CPP 4 does (statements separated by ';'). The text is the
     * attribute's value with XML entities already decoded. Never throws on bad input: errors come
     * back with their offsets in {@code text}.
     */
    public static ParsedScript parse(String text) {
        IParseResult result = parser().parse(new StringReader(text));
        EObject root = result.getRootASTElement();
        Script script = root instanceof Script ? (Script) root : AstFactory.eINSTANCE.createScript();
        List<ScriptSyntaxError> errors = new ArrayList<>();
        // What BT.CPP's grammar rejects and this one's cannot express: bad number suffixes come
        // first (they also confuse the parser), operator mixing needs a complete tree.
        NumberSuffixes.check(text, errors);
        if (errors.isEmpty()) {
            for (INode node : result.getSyntaxErrors()) {
                errors.add(new ScriptSyntaxError(node.getOffset(), node.getLength(),
                        SyntaxMessages.rephrase(node.getSyntaxErrorMessage().getMessage())));
            }
        }
        if (errors.isEmpty()) {
            OperatorGroups.check(script, errors);
        }
        return new ParsedScript(text, script, errors);
    }

    private static synchronized IParser parser() {
        if (parser == null) {
            parser = BtScriptStandaloneSetup.doSetup().getInstance(IParser.class);
        }
        return parser;
    }
}
