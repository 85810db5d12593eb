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
        List<ScriptSyntaxError> errors = new ArrayList<>();
        for (INode node : result.getSyntaxErrors()) {
            errors.add(new ScriptSyntaxError(node.getOffset(), node.getLength(),
                    node.getSyntaxErrorMessage().getMessage()));
        }
        EObject root = result.getRootASTElement();
        Script script = root instanceof Script ? (Script) root : AstFactory.eINSTANCE.createScript();
        return new ParsedScript(text, script, errors);
    }

    private static synchronized IParser parser() {
        if (parser == null) {
            parser = BtScriptStandaloneSetup.doSetup().getInstance(IParser.class);
        }
        return parser;
    }
}
