package org.miron.dsl.util;

import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Checks the cron string of a RoQME {@code schedule("...")}: the five fields of Unix cron, minute,
 * hour, day of month, month and day of week, each a comma-separated list of {@code *}, a value or
 * a range {@code a-b}, each optionally with a step {@code /n}; months and days of the week also by
 * their three-letter English names. A problem is located by its offset in the string, so that the
 * editor can underline the very field that is wrong.
 */
public final class CronSchedule {

    /** What is wrong and where, as an offset and length in the cron string. */
    public static final class Problem {
        public final String message;
        public final int offset;
        public final int length;

        Problem(String message, int offset, int length) {
            this.message = message;
            this.offset = offset;
            this.length = Math.max(length, 1);
        }
    }

    private static final class Field {
        final String name;
        final int min;
        final int max;
        final List<String> names; // index 0 is min

        Field(String name, int min, int max, List<String> names) {
            this.name = name;
            this.min = min;
            this.max = max;
            this.names = names;
        }
    }

    private static final List<Field> FIELDS = List.of(
            new Field("minute", 0, 59, List.of()),
            new Field("hour", 0, 23, List.of()),
            new Field("day of month", 1, 31, List.of()),
            new Field("month", 1, 12, List.of("JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC")),
            // 0 and 7 are both Sunday, as in Vixie cron
            new Field("day of week", 0, 7, List.of("SUN", "MON", "TUE", "WED", "THU", "FRI", "SAT")));

    private static final Pattern TOKEN = Pattern.compile("\\S+");
    private static final Pattern ITEM = Pattern.compile("(\\*|[^-/]+(?:-([^-/]+))?)(?:/(.*))?");

    private CronSchedule() {
    }

    /** The first problem of a cron string, or null when it is a valid five-field schedule. */
    public static Problem check(String cron) {
        Matcher tokens = TOKEN.matcher(cron);
        if (tokens.find() && tokens.group().startsWith("@")) {
            return new Problem("macros such as @daily are not cron fields: write the five fields, e.g. \"0 0 * * *\"",
                    tokens.start(), tokens.group().length());
        }
        tokens.reset();
        int count = 0;
        while (tokens.find()) {
            if (count == FIELDS.size()) {
                return new Problem("a schedule has 5 fields (minute hour day-of-month month day-of-week); '"
                        + tokens.group() + "' is one too many", tokens.start(), cron.length() - tokens.start());
            }
            Problem p = checkField(FIELDS.get(count), tokens.group(), tokens.start());
            if (p != null) {
                return p;
            }
            count++;
        }
        if (count < FIELDS.size()) {
            String missing = count == 0 ? "it is empty" : "the " + FIELDS.get(count).name + " is missing";
            return new Problem("a schedule has 5 fields (minute hour day-of-month month day-of-week); " + missing,
                    0, cron.length());
        }
        return null;
    }

    private static Problem checkField(Field field, String text, int start) {
        int at = 0;
        for (String item : text.split(",", -1)) {
            Problem p = checkItem(field, item, start + at);
            if (p != null) {
                return p;
            }
            at += item.length() + 1;
        }
        return null;
    }

    private static Problem checkItem(Field field, String item, int start) {
        Matcher m = ITEM.matcher(item);
        if (item.isEmpty() || !m.matches()) {
            return new Problem("'" + item + "' is not a valid " + field.name
                    + " (write *, a value, a range a-b or a list a,b; each may have a step /n)", start, item.length());
        }
        String range = m.group(1);
        if (m.group(3) != null) {
            int stepAt = start + m.start(3);
            Integer step = number(m.group(3));
            if (step == null || step < 1) {
                return new Problem("the step of the " + field.name + " must be a positive whole number, not '"
                        + m.group(3) + "'", stepAt, m.group(3).length());
            }
        }
        if (range.equals("*")) {
            return null;
        }
        int dash = m.group(2) == null ? -1 : range.indexOf('-');
        String from = dash < 0 ? range : range.substring(0, dash);
        Object lo = value(field, from, start);
        if (lo instanceof Problem) {
            return (Problem) lo;
        }
        if (dash < 0) {
            return null;
        }
        Object hi = value(field, m.group(2), start + dash + 1);
        if (hi instanceof Problem) {
            return (Problem) hi;
        }
        if ((Integer) lo > (Integer) hi) {
            return new Problem("the " + field.name + " range '" + range + "' is empty: it starts after it ends",
                    start, range.length());
        }
        return null;
    }

    /** The value of a field element: an Integer in the field's range, or a Problem. */
    private static Object value(Field field, String text, int start) {
        int byName = field.names.indexOf(text.toUpperCase(Locale.ROOT));
        if (byName >= 0) {
            return field.min + byName;
        }
        Integer v = number(text);
        if (v == null) {
            String names = field.names.isEmpty() ? "" : " or a name such as " + field.names.get(1);
            return new Problem("'" + text + "' is not a valid " + field.name + " (a number " + field.min + "-"
                    + field.max + names + ")", start, text.length());
        }
        if (v < field.min || v > field.max) {
            return new Problem(field.name + " " + v + " is outside " + field.min + "-" + field.max, start,
                    text.length());
        }
        return v;
    }

    private static Integer number(String text) {
        if (!text.matches("[0-9]{1,9}")) {
            return null;
        }
        return Integer.valueOf(text);
    }
}
