package org.miron.bt.scoping;

/** Scripts have no cross-references (names are blackboard keys, resolved at tick time). */
public class BtScriptScopeProvider extends AbstractBtScriptScopeProvider {
}
