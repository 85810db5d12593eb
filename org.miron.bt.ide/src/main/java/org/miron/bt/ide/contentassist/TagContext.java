package org.miron.bt.ide.contentassist;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where the caret is in an XML start tag, read from the text: completion must work while the
 * element is still incomplete and the parser has not made a model element of it.
 */
public record TagContext(Kind kind, String tag, String attribute, String partial, Map<String, String> attributes) {

    public enum Kind {
        /** Right after '<' or in the element name. */
        ELEMENT_NAME,
        /** Between attributes, or in an attribute's name. */
        ATTRIBUTE_NAME,
        /** Inside an attribute's quoted value. */
        ATTRIBUTE_VALUE,
        /** Anywhere else. */
        NONE
    }

    private static final Pattern NAME = Pattern.compile("[A-Za-z_][\\w.:-]*");
    private static final Pattern ATTRIBUTE = Pattern.compile("([A-Za-z_][\\w.:-]*)\\s*=\\s*(?:\"([^\"<]*)\"|'([^'<]*)')");
    private static final Pattern OPEN_VALUE = Pattern.compile("([A-Za-z_][\\w.:-]*)\\s*=\\s*[\"']([^\"'<]*)$");
    private static final Pattern ATTRIBUTE_START = Pattern.compile("\\s([A-Za-z_][\\w.:-]*)?$");

    private static final TagContext NONE = new TagContext(Kind.NONE, null, null, "", Map.of());

    public static TagContext at(String text, int offset) {
        if (offset < 1 || offset > text.length()) {
            return NONE;
        }
        int open = text.lastIndexOf('<', offset - 1);
        if (open < 0 || text.lastIndexOf('>', offset - 1) > open) {
            return NONE;
        }
        String before = text.substring(open + 1, offset);
        if (before.isEmpty() || NAME.matcher(before).matches()) {
            return new TagContext(Kind.ELEMENT_NAME, null, null, before, Map.of());
        }
        Matcher name = NAME.matcher(before);
        if (!name.lookingAt()) {
            return NONE; // a closing tag, comment or processing instruction
        }
        String tag = name.group();
        Map<String, String> attributes = attributesOf(text, open, offset);
        Matcher value = OPEN_VALUE.matcher(before);
        if (value.find() && insideQuotes(before)) {
            return new TagContext(Kind.ATTRIBUTE_VALUE, tag, value.group(1), value.group(2), attributes);
        }
        Matcher attribute = ATTRIBUTE_START.matcher(before);
        if (!insideQuotes(before) && attribute.find()) {
            String partial = attribute.group(1) == null ? "" : attribute.group(1);
            return new TagContext(Kind.ATTRIBUTE_NAME, tag, null, partial, attributes);
        }
        return NONE;
    }

    /** The complete attributes of the whole tag, also those after the caret. */
    private static Map<String, String> attributesOf(String text, int open, int offset) {
        int end = offset;
        while (end < text.length() && text.charAt(end) != '>' && text.charAt(end) != '<') {
            end++;
        }
        Map<String, String> attributes = new LinkedHashMap<>();
        Matcher matcher = ATTRIBUTE.matcher(text.substring(open, end));
        while (matcher.find()) {
            attributes.putIfAbsent(matcher.group(1), matcher.group(2) != null ? matcher.group(2) : matcher.group(3));
        }
        return attributes;
    }

    private static boolean insideQuotes(String tagText) {
        char quote = 0;
        for (char c : tagText.toCharArray()) {
            if (quote == 0 && (c == '"' || c == '\'')) {
                quote = c;
            } else if (c == quote) {
                quote = 0;
            }
        }
        return quote != 0;
    }
}
