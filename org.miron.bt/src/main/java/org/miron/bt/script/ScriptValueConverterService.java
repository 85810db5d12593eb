package org.miron.bt.script;

import org.eclipse.xtext.common.services.DefaultTerminalConverters;
import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.impl.AbstractNullSafeConverter;
import org.eclipse.xtext.nodemodel.INode;

/** Script strings are quoted without escapes: the value is the text between the quotes. */
public class ScriptValueConverterService extends DefaultTerminalConverters {

    @ValueConverter(rule = "QUOTED")
    public IValueConverter<String> QUOTED() {
        return new AbstractNullSafeConverter<String>() {
            @Override
            protected String internalToValue(String string, INode node) {
                return string.substring(1, string.length() - 1);
            }

            @Override
            protected String internalToString(String value) {
                return value.indexOf('\'') < 0 ? "'" + value + "'" : "\"" + value + "\"";
            }
        };
    }
}
