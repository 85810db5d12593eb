package org.miron.bt.validation;

/**
 * Checks of the scripting language beyond its grammar; scripts are validated where they occur, in
 * BT files, by BtValidator through ScriptChecks.
 */
public class BtScriptValidator extends AbstractBtScriptValidator {
}
