package org.miron.runtime.roqme.expr;

/**
 * The provider's variables by slot: contexts, params, vars, timers, beliefs and windows. A value is
 * a Double (numbers and times, in ms), Boolean, String (an enum literal), List (an array) or null
 * (unknown). A slot is <em>updated</em> in the step that wrote it; the step number saves clearing
 * flags between steps.
 */
public final class Store {
    public final Object[] values;
    private final long[] updatedStep;
    private long step;
    private long now;

    public Store(int slots) {
        values = new Object[slots];
        updatedStep = new long[slots];
    }

    /** Starts a new step at {@code time} (ms on the provider's clock). */
    public void newStep(long time) {
        step++;
        now = time;
    }

    public long now() {
        return now;
    }

    public void set(int slot, Object value) {
        values[slot] = value;
        updatedStep[slot] = step;
    }

    /** Marks a slot updated without a value (an event, a window that changed). */
    public void touch(int slot) {
        updatedStep[slot] = step;
    }

    public boolean updated(int slot) {
        return updatedStep[slot] == step;
    }

    /** True when any of the slots was updated in this step. */
    public boolean anyUpdated(int[] slots) {
        for (int s : slots) {
            if (updatedStep[s] == step) {
                return true;
            }
        }
        return false;
    }

    public Object get(int slot) {
        return values[slot];
    }
}
