package org.miron.runtime.requirement;

import java.util.Map;

/**
 * What a monitor tells as it happens: a requirement {@code violated} at instant {@code timeMs}, or
 * {@code met} again from {@code timeMs} on after a violation; known at {@code detectedMs} (later
 * when a window had to close first). {@code values}: every signal the requirement reads, at
 * {@code timeMs}, by the model's names.
 */
public record RequirementEvent(String name, String verdict, long timeMs, long detectedMs, Map<String, Object> values) {
    public static final String VIOLATED = "violated";
    public static final String MET = "met";

    /** {@code slowNearPeople violated: roqme.HumanDistance = 1.0, maxVelocity = 100}. */
    public String describe() {
        return name + " " + verdict + (values.isEmpty() ? "" : ": " + Signals.format(values));
    }

    /** Values as the console writes them: {@code roqme.HumanDistance = 1.0, maxVelocity = 100}. */
    public static String format(Map<String, Object> values) {
        return Signals.format(values);
    }

    /** A number of seconds as the console and reports write it: {@code 6.3}. */
    public static String seconds(long ms) {
        return Signals.number(ms / 1000.0);
    }
}
