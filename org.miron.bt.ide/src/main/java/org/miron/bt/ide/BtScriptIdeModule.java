package org.miron.bt.ide;

/** IDE services of the scripting language (generated defaults; scripts are edited inside BT files). */
public class BtScriptIdeModule extends AbstractBtScriptIdeModule {
}
