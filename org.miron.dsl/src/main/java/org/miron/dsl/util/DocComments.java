package org.miron.dsl.util;

/** Documentation comments (the DOC token, kept on the element it precedes) as plain text. */
public final class DocComments {

    private DocComments() {
    }

    /** "/** Wide open space. *&#47;" as "Wide open space.", leading "*" of each line removed; null stays null. */
    public static String plain(String documentation) {
        if (documentation == null) {
            return null;
        }
        String text = documentation.strip();
        if (text.startsWith("/**") && text.endsWith("*/")) {
            text = text.substring(3, text.length() - 2);
        }
        text = text.replaceAll("(?m)^\\s*\\*\\s?", "").strip();
        return text.isEmpty() ? null : text;
    }
}
