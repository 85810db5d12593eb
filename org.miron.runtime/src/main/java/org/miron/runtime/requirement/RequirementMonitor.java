package org.miron.runtime.requirement;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.miron.runtime.requirement.RequirementModel.Requirement;

/**
 * One requirement over a run. A top-level {@code always φ} (and {@code never φ}, that is always not
 * φ) is watched as episodes: each time φ turns false is a violation at that instant, each time it
 * turns true again after one is a {@code met}; a bounded one looks at φ up to its bound only. Any
 * other formula is decided once, at instant 0 of the run, when its windows have closed.
 */
final class RequirementMonitor {
    final Requirement spec;
    final int[] reads;
    private final FormulaNode root;
    private final FormulaNode body; // the top-level always' body, else null
    private final long bodyUntil;
    private boolean decided;
    private boolean inViolation;
    private long handled = -1; // start of the last body segment already told
    private int violations;
    private RequirementEvent first;
    private Truth rootValue = Truth.OPEN;
    private long openSince = -1;
    private boolean finishing;

    RequirementMonitor(Requirement spec, int[] reads, FormulaNode root, FormulaNode body, long bodyUntil) {
        this.spec = spec;
        this.reads = reads;
        this.root = root;
        this.body = body;
        this.bodyUntil = bodyUntil;
    }

    boolean finished() {
        return decided;
    }

    /** The oldest instant whose values this monitor may still report. */
    long pendingFrom() {
        return decided || body == null ? Long.MAX_VALUE : body.out.horizon();
    }

    void update(long now, Signals signals, Consumer<RequirementEvent> events) {
        if (decided) {
            return;
        }
        if (body == null) {
            root.update();
            if (root.out.size() > 0) {
                rootValue = root.out.value(0);
                decided = true;
                if (rootValue == Truth.FALSE) {
                    violation(now, now, signals, events);
                }
            }
            return;
        }
        body.update();
        Segments s = body.out;
        for (int i = 0; i < s.size(); i++) {
            long start = s.start(i);
            if (start <= handled) {
                continue;
            }
            if (start > bodyUntil) {
                decided = true;
                break;
            }
            handled = start;
            Truth v = s.value(i);
            long known = evaluableSince(signals);
            if (v == Truth.OPEN && finishing && openSince < 0 && s.end(i) > known) {
                openSince = Math.max(start, known); // a window reaching past the end, not a signal without value
            }
            if (v == Truth.FALSE && !inViolation) {
                inViolation = true;
                violation(start, now, signals, events);
            } else if (v == Truth.TRUE && inViolation) {
                inViolation = false;
                events.accept(new RequirementEvent(spec.name(), RequirementEvent.MET, start, now, signals.valuesAt(start, reads)));
            }
        }
        if (s.size() > 1) {
            s.dropBefore(s.start(s.size() - 1)); // the last one may still grow
        }
        if (s.horizon() > bodyUntil) {
            decided = true;
        }
    }

    /** From when on every signal it reads has had a value. */
    private long evaluableSince(Signals signals) {
        long t = 0;
        for (int r : reads) {
            t = Math.max(t, signals.firstKnown[r]);
        }
        return t;
    }

    private void violation(long time, long now, Signals signals, Consumer<RequirementEvent> events) {
        violations++;
        RequirementEvent e = new RequirementEvent(spec.name(), RequirementEvent.VIOLATED, time, now, signals.valuesAt(time, reads));
        if (first == null) {
            first = e;
        }
        events.accept(e);
    }

    RequirementResult finish(long end, Signals signals, Consumer<RequirementEvent> events) {
        finishing = true;
        if (!decided) {
            (body != null ? body : root).finish(end);
            update(end, signals, events);
        }
        List<String> never = new ArrayList<>();
        for (int r : reads) {
            if (!signals.everKnown[r]) {
                never.add(signals.defs[r].name());
            }
        }
        boolean open = body != null ? openSince >= 0 || (bodyUntil != Eventually.UNBOUNDED && bodyUntil > end)
                : rootValue == Truth.OPEN;
        Verdict v = violations > 0 ? Verdict.VIOLATED : !never.isEmpty() ? Verdict.NOT_EVALUATED
                : open ? Verdict.OPEN : Verdict.HOLDS;
        return new RequirementResult(spec.name(), v, violations, first, v == Verdict.OPEN ? Math.max(0, openSince) : -1,
                List.copyOf(never));
    }
}
