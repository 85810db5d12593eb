package org.miron.bt.nodes;

/**
 * How many child elements a built-in takes, from {@code min} to {@code max} (inclusive; {@link
 * #UNBOUNDED} for no limit): none for leaves and subtrees, exactly one for decorators, at least
 * one for most controls, 2 or 3 for IfThenElse, N+1 for SwitchN.
 */
public record Children(int min, int max) {
    public static final int UNBOUNDED = Integer.MAX_VALUE;
    public static final Children NONE = new Children(0, 0);
    public static final Children ONE = new Children(1, 1);
    public static final Children AT_LEAST_ONE = new Children(1, UNBOUNDED);

    public Children {
        if (min < 0 || max < min) {
            throw new IllegalArgumentException("children " + min + ".." + max);
        }
    }

    public static Children exactly(int count) {
        return new Children(count, count);
    }

    public static Children between(int min, int max) {
        return new Children(min, max);
    }

    public boolean admits(int count) {
        return count >= min && count <= max;
    }

    /** "none", "exactly 1", "at least 1", "2 or 3", "2 to 5". */
    public String describe() {
        if (max == 0) {
            return "none";
        }
        if (min == max) {
            return "exactly " + min;
        }
        if (max == UNBOUNDED) {
            return "at least " + min;
        }
        return min + (max == min + 1 ? " or " : " to ") + max;
    }
}
