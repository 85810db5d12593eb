/**
 * The scripting language of BehaviorTree.CPP 4, as used by {@code <Script code>},
 * {@code <ScriptCondition code>}, {@code <Precondition if>} and the pre/post-condition attributes
 * of any node ({@code _skipIf}, {@code _failureIf}, {@code _successIf}, {@code _while},
 * {@code _onSuccess}, {@code _onFailure}, {@code _post}, {@code _onHalted}).
 *
 * <p>The language is defined metamodel-first: {@code model/btscript.ecore} (the AST, generated into
 * {@link org.miron.bt.script.ast}) and the Xtext grammar {@code org/miron/bt/BtScript.xtext}. It has
 * no file format of its own; attribute values are parsed with
 * {@link org.miron.bt.script.BtScripts#parse(String)}, which returns a {@link
 * org.miron.bt.script.ParsedScript}: the {@link org.miron.bt.script.ast.Script} root (its
 * statements, each an {@link org.miron.bt.script.ast.Expression}) and the syntax errors with
 * offsets into the parsed text. The BT validator maps those offsets back into the XML file.
 *
 * <p>Syntax, as BehaviorTree.CPP 4's lexy grammar: statements separated by {@code ;}; assignment
 * {@code :=} (create), {@code =} (existing), {@code += -= *= /=}; conditional {@code c ? a : b};
 * {@code &&} and {@code ||} (one precedence level, left to right); comparison chains
 * {@code == != < <= > >=}; string concatenation {@code ..}; bitwise {@code | ^ &}; arithmetic
 * {@code + - * /}; prefix {@code - ! ~}; integers (also {@code 0x2A}), reals, strings in single
 * (or double) quotes without escapes, {@code true}/{@code false}, names (blackboard keys, {@code @key}
 * for the root blackboard, or enum names) and parentheses.
 * {@link org.miron.bt.script.ScriptLiterals} gives number values.
 */
package org.miron.bt.script;
