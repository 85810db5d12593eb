package org.miron.dsl.conversion;

import org.eclipse.xtext.common.services.DefaultTerminalConverters;
import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.nodemodel.INode;

/**
 * Numbers of both languages. A number missing after a syntax error converts silently (to 0 for
 * the primitive features, to null for the optional ones), so the user sees the syntax error alone,
 * not a conversion error on top of it; the validator skips elements with syntax errors.
 */
public class DslValueConverterService extends DefaultTerminalConverters {

    private static final IValueConverter<Double> DOUBLE = new NumberConverter(0.0);
    private static final IValueConverter<Double> OPTIONAL_DOUBLE = new NumberConverter(null);

    private static final class NumberConverter implements IValueConverter<Double> {
        private final Double missing;

        NumberConverter(Double missing) {
            this.missing = missing;
        }

        @Override
        public Double toValue(String string, INode node) {
            if (string == null || string.isEmpty()) {
                return missing;
            }
            try {
                return Double.valueOf(string);
            } catch (NumberFormatException e) {
                throw new ValueConverterException("'" + string + "' is not a number", node, e);
            }
        }

        @Override
        public String toString(Double value) {
            if (value == null) {
                throw new ValueConverterException("a number is required", null, null);
            }
            return value == Math.rint(value) && Math.abs(value) < 1e15 ? String.valueOf(value.longValue())
                    : String.valueOf(value);
        }
    }

    /** A unit written as a string or as a plain word: the quotes are not part of it. */
    @ValueConverter(rule = "UnitName")
    public IValueConverter<String> unitName() {
        return new IValueConverter<String>() {
            @Override
            public String toValue(String string, INode node) {
                return string != null && string.startsWith("\"") ? STRING().toValue(string, node) : string;
            }

            @Override
            public String toString(String value) {
                return value != null && value.matches("[a-zA-Z_][a-zA-Z_0-9]*") ? value : STRING().toString(value);
            }
        };
    }

    /**
     * Enum literal references: the serializer hands over the literal's qualified name joined with
     * dots (the name converter's default); the syntax joins the segments with "::".
     */
    @ValueConverter(rule = "EnumLiteralName")
    public IValueConverter<String> enumLiteralName() {
        return new IValueConverter<String>() {
            @Override
            public String toValue(String string, INode node) {
                return string;
            }

            @Override
            public String toString(String value) {
                return value == null ? null : value.replace("::", ".").replace(".", "::");
            }
        };
    }

    @ValueConverter(rule = "Number")
    public IValueConverter<Double> number() {
        return DOUBLE;
    }

    @ValueConverter(rule = "UnsignedNumber")
    public IValueConverter<Double> unsignedNumber() {
        return DOUBLE;
    }

    @ValueConverter(rule = "NumberObject")
    public IValueConverter<Double> numberObject() {
        return OPTIONAL_DOUBLE;
    }
}
