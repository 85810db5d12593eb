package org.miron.bt.conversion;

/** XML attribute-value escaping: the model holds plain text, the file holds entities. */
public final class XmlStrings {
    private XmlStrings() {
    }

    /** Decodes the five predefined entities and numeric character references. */
    public static String unescape(String text) {
        if (text.indexOf('&') < 0) {
            return text;
        }
        StringBuilder out = new StringBuilder(text.length());
        int i = 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            int semicolon = c == '&' ? text.indexOf(';', i) : -1;
            if (semicolon < 0) {
                out.append(c);
                i++;
                continue;
            }
            String entity = text.substring(i + 1, semicolon);
            String decoded = decode(entity);
            if (decoded == null) {
                throw new IllegalArgumentException("unknown XML entity '&" + entity + ";'");
            }
            out.append(decoded);
            i = semicolon + 1;
        }
        return out.toString();
    }

    private static String decode(String entity) {
        switch (entity) {
        case "lt": return "<";
        case "gt": return ">";
        case "amp": return "&";
        case "quot": return "\"";
        case "apos": return "'";
        default:
            try {
                if (entity.startsWith("#x") || entity.startsWith("#X")) {
                    return new String(Character.toChars(Integer.parseInt(entity.substring(2), 16)));
                }
                if (entity.startsWith("#")) {
                    return new String(Character.toChars(Integer.parseInt(entity.substring(1))));
                }
            } catch (IllegalArgumentException e) {
                return null;
            }
            return null;
        }
    }

    /** The value as a double-quoted XML attribute, escaping what XML requires. */
    public static String quote(String value) {
        StringBuilder out = new StringBuilder(value.length() + 2).append('"');
        for (int i = 0; i < value.length(); i++) {
            char c = value.charAt(i);
            switch (c) {
            case '<': out.append("&lt;"); break;
            case '>': out.append("&gt;"); break;
            case '&': out.append("&amp;"); break;
            case '"': out.append("&quot;"); break;
            default: out.append(c);
            }
        }
        return out.append('"').toString();
    }
}
