package org.miron.runtime.roqme.expr;

/**
 * The pattern operators of the RoQME syntax guide (docs/roqme-provider.md, "Patterns"). Children
 * are always evaluated, left then right, so their state follows every step.
 */
final class Events {
    private Events() {
    }

    /** An eventtype context or a timer, or {@code update(x)} of a plain variable: every update with a known value. */
    static EventNode source(int slot, boolean needsValue) {
        return s -> s.updated(slot) && (!needsValue || s.values[slot] != null);
    }

    /**
     * {@code update(e)} of a compound expression: its value changed (or became known) after one of
     * its variables was updated; {@code eventWhen(e)} ({@code whenTrue}): it became true.
     */
    static EventNode change(ValueNode e, int[] deps, boolean whenTrue) {
        return new EventNode() {
            private Object last;

            @Override
            public boolean occurs(Store s) {
                if (!s.anyUpdated(deps)) {
                    return false;
                }
                Object v = e.eval(s);
                Object before = last;
                last = v;
                if (v == null) {
                    return false; // unknown: never an event
                }
                if (whenTrue) {
                    return Boolean.TRUE.equals(v) && !Boolean.TRUE.equals(before);
                }
                return before == null || !before.equals(v);
            }
        };
    }

    /** {@code eventWhen(x)} of a plain boolean variable: an update that makes it true (from false or unknown). */
    static EventNode becameTrue(int slot) {
        return change(Values.ref(slot), new int[] {slot}, true);
    }

    static EventNode or(EventNode a, EventNode b) {
        return s -> a.occurs(s) | b.occurs(s);
    }

    /** Both have occurred, in any order, since the pattern last fired. */
    static EventNode and(EventNode a, EventNode b) {
        return new EventNode() {
            private boolean seenA;
            private boolean seenB;

            @Override
            public boolean occurs(Store s) {
                seenA |= a.occurs(s);
                seenB |= b.occurs(s);
                if (seenA && seenB) {
                    seenA = seenB = false;
                    return true;
                }
                return false;
            }
        };
    }

    /**
     * {@code A and not B}: A when B has not occurred since the pattern (re)started, i.e. since its
     * last occurrence of A (fired or not). B in the same step as A counts as occurred.
     */
    static EventNode andNot(EventNode a, EventNode b) {
        return new EventNode() {
            private boolean seenB;

            @Override
            public boolean occurs(Store s) {
                boolean x = a.occurs(s);
                seenB |= b.occurs(s);
                if (x) {
                    boolean fire = !seenB;
                    seenB = false;
                    return fire;
                }
                return false;
            }
        };
    }

    /** {@code A -> B}: a B after an A; each A is matched by the first B after it (not one in the same step). */
    static EventNode followedBy(EventNode a, EventNode b) {
        return new EventNode() {
            private boolean pending;

            @Override
            public boolean occurs(Store s) {
                boolean x = a.occurs(s);
                boolean y = b.occurs(s);
                boolean fire = pending && y;
                if (fire) {
                    pending = false;
                }
                if (x) {
                    pending = true;
                }
                return fire;
            }
        };
    }

    /** {@code P repeat(n)}: every n-th occurrence. */
    static EventNode repeat(EventNode p, int n) {
        return new EventNode() {
            private int count;

            @Override
            public boolean occurs(Store s) {
                if (p.occurs(s) && ++count >= n) {
                    count = 0;
                    return true;
                }
                return false;
            }
        };
    }

    /** {@code P range(a, b)}: the a-th to b-th occurrences; counting starts again after the b-th. */
    static EventNode range(EventNode p, int min, int max) {
        return new EventNode() {
            private int count;

            @Override
            public boolean occurs(Store s) {
                if (!p.occurs(s)) {
                    return false;
                }
                count++;
                boolean fire = count >= min && count <= max;
                if (count >= max) {
                    count = 0;
                }
                return fire;
            }
        };
    }

    /** {@code once P}: the first occurrence ever. */
    static EventNode once(EventNode p) {
        return new EventNode() {
            private boolean done;

            @Override
            public boolean occurs(Store s) {
                boolean x = p.occurs(s);
                if (x && !done) {
                    done = true;
                    return true;
                }
                return false;
            }
        };
    }

    /** {@code P while (C)}: P occurs while C is true at that instant (unknown C: no). */
    static EventNode whileTrue(EventNode p, ValueNode c) {
        return s -> p.occurs(s) && Boolean.TRUE.equals(c.eval(s));
    }
}
