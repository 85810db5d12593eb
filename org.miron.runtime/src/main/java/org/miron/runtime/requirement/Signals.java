package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.miron.runtime.requirement.RequirementModel.Signal;

/**
 * The signals' current values, piecewise constant: a context holds the value last published, a
 * property the estimate last computed, a varpoint the value last applied; an event context is true
 * only at the instant it occurs. Numbers as they are, Booleans as 1/0, enum literals and varpoint
 * values by index; NaN before the first value. Keeps the values of the recent past (what a monitor
 * may still report a violation at), trimmed to what the monitors still need.
 */
final class Signals {
    final Signal[] defs;
    /** By signal index; the expression pool's parameter slots are the signal indices. */
    final double[] value;
    /** By varpoint slot: the pool's assignment (the value index). */
    final int[] assign;
    final int[] vpSlot;
    final boolean[] everKnown;
    /** When each signal first had a value (Long.MAX_VALUE: not yet). */
    final long[] firstKnown;
    private long now;
    final List<List<Atom>> readers = new ArrayList<>();
    boolean changed;
    boolean pulsed;

    private long[] times = new long[16];
    private double[][] snapshots = new double[16][];
    private int head;
    private int size;

    Signals(List<Signal> signals) {
        defs = signals.toArray(new Signal[0]);
        value = new double[defs.length];
        vpSlot = new int[defs.length];
        everKnown = new boolean[defs.length];
        firstKnown = new long[defs.length];
        Arrays.fill(firstKnown, Long.MAX_VALUE);
        int slots = 0;
        for (int i = 0; i < defs.length; i++) {
            readers.add(new ArrayList<>());
            vpSlot[i] = defs[i].isVarpoint() ? slots++ : -1;
            value[i] = Double.NaN;
            if (defs[i].isVarpoint() && defs[i].initial() != null) {
                value[i] = defs[i].initial();
                everKnown[i] = true;
                firstKnown[i] = 0;
            } else if (defs[i].isEvent()) {
                value[i] = 0; // no event yet: not happening
                everKnown[i] = true;
                firstKnown[i] = 0;
            }
        }
        assign = new int[slots];
        for (int i = 0; i < defs.length; i++) {
            if (vpSlot[i] >= 0 && !Double.isNaN(value[i])) {
                assign[vpSlot[i]] = (int) value[i];
            }
        }
    }

    /** The instant the next values belong to. */
    void at(long t) {
        now = t;
    }

    void set(int signal, double v) {
        if (defs[signal].isEvent() && v != 0) {
            pulsed = true;
        }
        if (!everKnown[signal]) {
            everKnown[signal] = true;
            firstKnown[signal] = now;
        }
        if (Double.compare(value[signal], v) == 0 && !defs[signal].isEvent()) {
            return;
        }
        value[signal] = v;
        if (vpSlot[signal] >= 0) {
            assign[vpSlot[signal]] = (int) v;
        }
        changed = true;
        for (Atom a : readers.get(signal)) {
            a.dirty = true;
        }
    }

    /** After an instant with events: they are over. */
    void endPulses() {
        for (int i = 0; i < defs.length; i++) {
            if (defs[i].isEvent() && value[i] != 0) {
                set(i, 0);
            }
        }
        pulsed = false;
    }

    /** Remembers the values from instant {@code t} on, when something changed. */
    void record(long t) {
        if (!changed && size > 0) {
            return;
        }
        changed = false;
        if (size > 0 && times[index(size - 1)] == t) {
            snapshots[index(size - 1)] = value.clone();
            return;
        }
        if (size == times.length) {
            long[] nt = new long[size * 2];
            double[][] ns = new double[size * 2][];
            for (int i = 0; i < size; i++) {
                nt[i] = times[index(i)];
                ns[i] = snapshots[index(i)];
            }
            times = nt;
            snapshots = ns;
            head = 0;
        }
        times[index(size)] = t;
        snapshots[index(size)] = value.clone();
        size++;
    }

    /** Forgets what held before {@code t}, keeping the values in force at {@code t}. */
    void forgetBefore(long t) {
        while (size > 1 && times[index(1)] <= t) {
            snapshots[head] = null;
            head = (head + 1) % times.length;
            size--;
        }
    }

    int remembered() {
        return size;
    }

    private int index(int i) {
        return (head + i) % times.length;
    }

    /** The values of {@code reads} in force at instant {@code t}, by signal name (null: no value yet). */
    Map<String, Object> valuesAt(long t, int[] reads) {
        double[] snap = value;
        for (int i = size - 1; i >= 0; i--) {
            if (times[index(i)] <= t) {
                snap = snapshots[index(i)];
                break;
            }
        }
        Map<String, Object> out = new LinkedHashMap<>();
        for (int s : reads) {
            out.put(defs[s].name(), display(defs[s], snap[s]));
        }
        return out;
    }

    /** A value as the model writes it: a number, true/false, an enum literal or a varpoint's value. */
    static Object display(Signal s, double v) {
        if (Double.isNaN(v)) {
            return null;
        }
        if (s.isVarpoint()) {
            JsonNode x = s.literals().get((int) v);
            return x.isNumber() ? x.numberValue() : x.isBoolean() ? (Object) x.asBoolean() : x.asText();
        }
        return switch (s.type()) {
            case "boolean", "event" -> v != 0;
            case "enum" -> s.literals().get((int) v).asText();
            default -> v;
        };
    }

    /** {@code roqme.HumanDistance = 1.0, maxVelocity = 100}: numbers to three decimals at most. */
    static String format(Map<String, Object> values) {
        StringBuilder b = new StringBuilder();
        values.forEach((k, v) -> {
            if (b.length() > 0) {
                b.append(", ");
            }
            b.append(k).append(" = ").append(v == null ? "(no value)" : v instanceof Double d ? number(d) : v);
        });
        return b.toString();
    }

    static String number(double d) {
        if (!Double.isFinite(d)) {
            return String.valueOf(d);
        }
        BigDecimal x = new BigDecimal(d).setScale(3, RoundingMode.HALF_UP).stripTrailingZeros();
        return x.scale() <= 0 ? x.setScale(1).toPlainString() : x.toPlainString();
    }

    @Override
    public String toString() {
        return Arrays.toString(value);
    }
}
