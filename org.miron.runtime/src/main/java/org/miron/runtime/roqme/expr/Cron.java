package org.miron.runtime.roqme.expr;

import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.BitSet;
import java.util.List;
import java.util.Locale;

/**
 * A 5-field Unix cron schedule ({@code m h dom mon dow}: values, ranges, lists, steps, month and
 * day names) on the provider's clock, in UTC. As in Vixie cron, when both day fields are
 * restricted a day matches either.
 */
public final class Cron {
    private static final List<String> MONTHS = List.of("JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC");
    private static final List<String> DAYS = List.of("SUN", "MON", "TUE", "WED", "THU", "FRI", "SAT");
    private final BitSet minute;
    private final BitSet hour;
    private final BitSet dom;
    private final BitSet month;
    private final BitSet dow;
    private final boolean domStar;
    private final boolean dowStar;

    private Cron(String[] f) {
        minute = field(f[0], 0, 59, null, "minute");
        hour = field(f[1], 0, 23, null, "hour");
        dom = field(f[2], 1, 31, null, "day of month");
        month = field(f[3], 1, 12, MONTHS, "month");
        dow = field(f[4], 0, 7, DAYS, "day of week");
        if (dow.get(7)) {
            dow.set(0);
        }
        domStar = f[2].startsWith("*");
        dowStar = f[4].startsWith("*");
    }

    public static Cron parse(String text) {
        String[] f = text.trim().split("\\s+");
        if (f.length != 5) {
            throw new IllegalArgumentException("a schedule has 5 fields (m h dom mon dow), got '" + text + "'");
        }
        return new Cron(f);
    }

    private static BitSet field(String text, int lo, int hi, List<String> names, String what) {
        BitSet b = new BitSet();
        for (String part : text.split(",")) {
            String[] step = part.split("/", -1);
            int by = 1;
            if (step.length == 2) {
                by = number(step[1], null, 0, what);
                if (by < 1) {
                    throw new IllegalArgumentException("bad step in the " + what + " field '" + text + "'");
                }
            } else if (step.length > 2) {
                throw new IllegalArgumentException("bad " + what + " field '" + text + "'");
            }
            int a;
            int z;
            if (step[0].equals("*")) {
                a = lo;
                z = hi;
            } else {
                String[] r = step[0].split("-", -1);
                a = number(r[0], names, lo, what);
                z = r.length == 2 ? number(r[1], names, lo, what) : step.length == 2 ? hi : a;
                if (r.length > 2) {
                    throw new IllegalArgumentException("bad " + what + " field '" + text + "'");
                }
            }
            if (a < lo || z > hi || a > z) {
                throw new IllegalArgumentException(what + " out of range " + lo + "-" + hi + " in '" + text + "'");
            }
            for (int i = a; i <= z; i += by) {
                b.set(i);
            }
        }
        return b;
    }

    private static int number(String s, List<String> names, int lo, String what) {
        if (names != null) {
            int i = names.indexOf(s.toUpperCase(Locale.ROOT));
            if (i >= 0) {
                return i + (names.size() == 12 ? 1 : 0);
            }
        }
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("bad " + what + " value '" + s + "'");
        }
    }

    /** The first matching minute strictly after {@code ms} (epoch ms), or -1 within 5 years. */
    public long next(long ms) {
        LocalDateTime t = LocalDateTime.ofInstant(Instant.ofEpochMilli(ms), ZoneOffset.UTC)
                .withSecond(0).withNano(0).plusMinutes(1);
        LocalDateTime end = t.plusYears(5);
        while (t.isBefore(end)) {
            if (!month.get(t.getMonthValue())) {
                t = t.withDayOfMonth(1).withHour(0).withMinute(0).plusMonths(1);
            } else if (!dayMatches(t)) {
                t = t.withHour(0).withMinute(0).plusDays(1);
            } else if (!hour.get(t.getHour())) {
                t = t.withMinute(0).plusHours(1);
            } else if (!minute.get(t.getMinute())) {
                t = t.plusMinutes(1);
            } else {
                return t.toInstant(ZoneOffset.UTC).toEpochMilli();
            }
        }
        return -1;
    }

    private boolean dayMatches(LocalDateTime t) {
        boolean d = dom.get(t.getDayOfMonth());
        boolean w = dow.get(t.getDayOfWeek().getValue() % 7);
        if (domStar || dowStar) {
            return d && w;
        }
        return d || w;
    }
}
