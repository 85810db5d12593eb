package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.miron.runtime.roqme.Harness.ref;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import org.miron.runtime.roqme.expr.Cron;

/** Timers as events: period, offset, onetime, paused, schedule, and the starts/stops/resumes actions. */
public class TimersTest {
    private static String act(String kind, String timer) {
        return "{\"kind\":\"" + kind + "\",\"timer\":\"" + timer + "\"}";
    }

    /** Times at which observation o (the timer as pattern) fired up to {@code until}, advancing in 100 ms steps. */
    private static List<Long> firings(Harness h, long from, long until) {
        List<Long> times = new ArrayList<>();
        for (long t = from; t <= until; t += 100) {
            if (h.until(t).contains("o")) {
                times.add(t);
            }
        }
        return times;
    }

    @Test
    public void periodicTimerFiresEveryPeriod() throws Exception {
        Harness h = new Harness().timer("tick", 1000L, null, 0, false, false).obs("o", ref("tick")).start();
        assertEquals(List.of(1000L, 2000L, 3000L), firings(h, 100, 3000));
    }

    @Test
    public void offsetDelaysTheFirstFiring() throws Exception {
        Harness h = new Harness().timer("tick", 1000L, null, 500, false, false).obs("o", ref("tick")).start();
        assertEquals(List.of(1500L, 2500L, 3500L), firings(h, 100, 3500));
    }

    @Test
    public void onetimeFiresOnce() throws Exception {
        Harness h = new Harness().timer("tick", 1000L, null, 0, true, false).obs("o", ref("tick")).start();
        assertEquals(List.of(1000L), firings(h, 100, 5000));
    }

    @Test
    public void pausedTimerWaitsForStarts() throws Exception {
        // timer overdue onetime paused := 2 s; observation : e starts overdue
        Harness h = new Harness().timer("overdue", 2000L, null, 0, true, true)
                .obs("s", ref("e"), act("starts", "overdue")).obs("o", ref("overdue")).start();
        assertEquals(List.of(), firings(h, 100, 5000));
        h.in("e", true, 5050);
        h.in("e", true, 6050); // restarted: fires 2 s after the last one
        assertEquals(List.of(8100L), firings(h, 6100, 12000));
    }

    @Test
    public void stopsAndResumesContinueFromTheTimeLeft() throws Exception {
        Harness h = new Harness().timer("tick", 1000L, null, 0, false, false)
                .obs("stop", ref("e"), act("stops", "tick")).obs("go", ref("f"), act("resumes", "tick"))
                .obs("o", ref("tick")).start();
        assertEquals(List.of(1000L), firings(h, 100, 1000));
        h.in("e", true, 1300); // 700 ms left
        assertEquals(List.of(), firings(h, 1400, 4000));
        h.in("f", true, 4000);
        assertEquals(List.of(4700L, 5700L), firings(h, 4100, 5700));
    }

    @Test
    public void scheduleFiresAtItsCronTimes() throws Exception {
        Harness h = new Harness().timer("quarter", null, "*/15 * * * *", 0, false, false).obs("o", ref("quarter")).start();
        List<Long> times = new ArrayList<>();
        for (long t = 0; t <= 3_600_000; t += 60_000) {
            if (h.until(t).contains("o")) {
                times.add(t);
            }
        }
        assertEquals(List.of(900_000L, 1_800_000L, 2_700_000L, 3_600_000L), times);
    }

    @Test
    public void scheduleCallInAPatternIsATimer() throws Exception {
        Harness h = new Harness().obs("o", "{\"call\":\"schedule\",\"args\":[{\"string\":\"0 * * * *\"}]}").start();
        List<Long> times = new ArrayList<>();
        for (long t = 0; t <= 3 * 3_600_000; t += 60_000) {
            if (h.until(t).contains("o")) {
                times.add(t);
            }
        }
        assertEquals(List.of(3_600_000L, 7_200_000L, 10_800_000L), times);
    }

    @Test
    public void cronFields() {
        long t0 = Instant.parse("2026-11-26T05:00:00Z").toEpochMilli(); // a Thursday
        assertEquals(Instant.parse("2026-11-26T08:00:00Z").toEpochMilli(), Cron.parse("0 8-18/2 * * *").next(t0));
        assertEquals(Instant.parse("2026-11-30T00:30:00Z").toEpochMilli(), Cron.parse("30 0 * * MON").next(t0));
        assertEquals(Instant.parse("2027-01-01T00:00:00Z").toEpochMilli(), Cron.parse("0 0 1 jan *").next(t0));
        // both day fields restricted: either matches (the 1st or a Sunday)
        assertEquals(Instant.parse("2026-11-29T00:00:00Z").toEpochMilli(), Cron.parse("0 0 1 * 0").next(t0));
        for (String bad : List.of("* * *", "60 * * * *", "* * * * L", "*/0 * * * *", "5-1 * * * *")) {
            try {
                Cron.parse(bad);
                throw new AssertionError("accepted " + bad);
            } catch (IllegalArgumentException e) {
                assertTrue(e.getMessage(), !e.getMessage().isEmpty());
            }
        }
    }
}
