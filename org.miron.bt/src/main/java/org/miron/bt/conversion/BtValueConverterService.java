package org.miron.bt.conversion;

import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.conversion.ValueConverterException;
import org.eclipse.xtext.conversion.impl.AbstractDeclarativeValueConverterService;
import org.eclipse.xtext.conversion.impl.AbstractNullSafeConverter;
import org.eclipse.xtext.nodemodel.INode;

import com.google.inject.Inject;

/** Value conversion for the BT grammar: quoted XML attribute values with entities. */
public class BtValueConverterService extends AbstractDeclarativeValueConverterService {

    @Inject
    private XmlStringConverter stringConverter;

    @ValueConverter(rule = "STRING")
    public IValueConverter<String> STRING() {
        return stringConverter;
    }

    /** Strips the quotes (single or double) and decodes entities; writes double-quoted values. */
    public static class XmlStringConverter extends AbstractNullSafeConverter<String> {
        @Override
        protected String internalToValue(String string, INode node) {
            if (string.length() < 2) {
                throw new ValueConverterException("unterminated attribute value", node, null);
            }
            try {
                return XmlStrings.unescape(string.substring(1, string.length() - 1));
            } catch (IllegalArgumentException e) {
                throw new ValueConverterException(e.getMessage(), node, e);
            }
        }

        @Override
        protected String internalToString(String value) {
            return XmlStrings.quote(value);
        }
    }
}
