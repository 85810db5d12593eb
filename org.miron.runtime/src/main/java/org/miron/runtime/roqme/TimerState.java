package org.miron.runtime.roqme;

import org.miron.runtime.roqme.expr.Cron;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * One timer's schedule on the provider's clock. Armed at time s (the provider's start unless
 * {@code paused}, or a {@code starts}), a periodic timer fires at s + offset + period, then every
 * period (once with {@code onetime}); a schedule timer at its cron times after s. {@code stops}
 * keeps the time left to the next firing and {@code resumes} continues from it (a never-armed
 * timer resumes as if started).
 */
final class TimerState {
    final RoqmeModel.Timer decl;
    final int slot;
    private final Cron cron;
    private long next = -1; // due time, -1 when not armed
    private long left = -1; // time left when stopped, -1 when none
    int generation; // bumps on every change: stale queue entries are ignored

    TimerState(RoqmeModel.Timer decl, int slot) {
        this.decl = decl;
        this.slot = slot;
        this.cron = decl.schedule() == null ? null : Cron.parse(decl.schedule());
    }

    long next() {
        return next;
    }

    void start(long now) {
        next = cron != null ? cron.next(now) : now + decl.offsetMs() + decl.periodMs();
        left = -1;
        generation++;
    }

    void stop(long now) {
        if (next >= 0) {
            left = next - now;
        }
        next = -1;
        generation++;
    }

    void resume(long now) {
        if (next >= 0) {
            return; // running already
        }
        if (left < 0 || cron != null) {
            start(now);
        } else {
            next = now + left;
            left = -1;
            generation++;
        }
    }

    /** Called when it fires at {@code now}: schedules the next firing. */
    void fired(long now) {
        next = decl.onetime() ? -1 : cron != null ? cron.next(now) : now + decl.periodMs();
        generation++;
    }
}
