package org.miron.dsl.ide.hover;

import java.util.Map;

/**
 * What each RoQME function does (docs/languages.md, the RoQME runtime's semantics), for hovers: a
 * signature and one sentence. Aggregates take a window of time ({@code avg(x, 30 seconds)}) or of
 * samples ({@code avg(x, 10)}); every function is also callable as {@code x'fn(args)}.
 */
final class RoqmeFunctions {
    private static final String WINDOW = " over a window of time (`30 seconds`, sliding) or of samples (`10`: the last 10)";
    private static final Map<String, String> FUNCTIONS = Map.ofEntries(
            Map.entry("pow", "pow(x, y): x to the power y"),
            Map.entry("sqrt", "sqrt(x): the square root of x"),
            Map.entry("exp", "exp(x): e to the power x"),
            Map.entry("abs", "abs(x): the absolute value of x"),
            Map.entry("avg", "avg(x, window): the average of x's samples" + WINDOW),
            Map.entry("min", "min(x, window): the smallest of x's samples" + WINDOW),
            Map.entry("max", "max(x, window): the largest of x's samples" + WINDOW),
            Map.entry("count", "count(e, window): how many times the event e occurred" + WINDOW),
            Map.entry("sum", "sum(x, window): the sum of x's samples" + WINDOW),
            Map.entry("decreasing", "decreasing(x, window): whether x's samples fall" + WINDOW),
            Map.entry("increasing", "increasing(x, window): whether x's samples rise" + WINDOW),
            Map.entry("stable", "stable(x, window): whether x's samples stay equal" + WINDOW),
            Map.entry("eventWhen", "eventWhen(e): an event each time the boolean e becomes true"),
            Map.entry("update", "update(x): an event at every sample of x (of an expression: when its value changes)"),
            Map.entry("period", "period(x): the time between the last two updates of x"),
            Map.entry("first", "first(s): the first element of the sequence s"),
            Map.entry("last", "last(s): the last element of the sequence s"),
            Map.entry("at", "at(s, i): the element of the sequence s at index i"),
            Map.entry("size", "size(s): the number of elements of the sequence s"),
            Map.entry("isEmpty", "isEmpty(s): whether the sequence s has no element"),
            Map.entry("includes", "includes(s, x): whether the sequence s holds x"),
            Map.entry("schedule", "schedule(\"m h dom mon dow\"): a timer's times, from a five-field Unix cron string"));

    private RoqmeFunctions() {
    }

    /** Markdown for a function's hover, or null for a name that is no function. */
    static String describe(String function) {
        String text = FUNCTIONS.get(function);
        if (text == null) {
            return null;
        }
        int colon = text.indexOf(": ");
        return "**function** `" + text.substring(0, colon) + "`\n\n" + text.substring(colon + 2) + ".";
    }
}
