package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.util.List;

import org.junit.Test;
import org.miron.dsl.util.CronSchedule;

/** The five-field cron syntax of schedule("..."), and where in the string a problem is reported. */
public class CronScheduleTest {

    @Test
    public void unixCronIsAccepted() {
        for (String cron : List.of("* * * * *", "0 8 * * *", "*/15 8-18 * * 1-5", "0 0 1 */3 *", "5/15 * * * *",
                "0,15,30,45 */2 1-31/2 6 sun", "0 8 * JAN-MAR,dec MON-FRI", "59 23 31 12 7", "0 0 1 1 0",
                "  0\t8 * * *  ", "0 8-8 * * *", "0 0-23/1 * * *")) {
            CronSchedule.Problem p = CronSchedule.check(cron);
            assertNull(cron + ": " + (p == null ? "" : p.message), p);
        }
    }

    /** Each wrong string, the offset and length of the reported text, and a word of the message. */
    @Test
    public void problemsAreLocated() {
        Object[][] cases = {
            { "", 0, 1, "it is empty" },
            { "0 8 * *", 0, 7, "the day of week is missing" },
            { "0 0 8 * * *", 10, 1, "one too many" },
            { "0 8 * * * 2026 x", 10, 6, "'2026' is one too many" },
            { "60 * * * *", 0, 2, "minute 60 is outside 0-59" },
            { "0 8,24 * * *", 4, 2, "hour 24" },
            { "0 8 0 * *", 4, 1, "day of month 0" },
            { "0 8 * 0 *", 6, 1, "month 0" },
            { "0 8 * * 1-8", 10, 1, "day of week 8" },
            { "0 8 * * MON-FRY", 12, 3, "'FRY' is not a valid day of week" },
            { "0 8 * FEBR *", 6, 4, "'FEBR' is not a valid month" },
            { "0 8 * * MON/0", 12, 1, "step" },
            { "*/ * * * *", 2, 1, "step" },
            { "*/x * * * *", 2, 1, "step" },
            { "0 18-8 * * *", 2, 4, "range '18-8' is empty" },
            { "0 8,,9 * * *", 4, 1, "'' is not a valid hour" },
            { "1- * * * *", 0, 2, "'1-' is not a valid minute" },
            { "-1 * * * *", 0, 2, "'-1' is not a valid minute" },
            { "*-5 * * * *", 0, 1, "'*' is not a valid minute" },
            { "0 8 L * *", 4, 1, "'L' is not a valid day of month" },
            { "0 8 ? * *", 4, 1, "'?' is not a valid day of month" },
            { "0 8 * * 1#2", 8, 3, "day of week" },
            { "@daily", 0, 6, "macros" },
        };
        for (Object[] c : cases) {
            String cron = (String) c[0];
            CronSchedule.Problem p = CronSchedule.check(cron);
            assertNotNull(cron, p);
            assertEquals(cron + ": " + p.message, c[1], p.offset);
            assertEquals(cron + ": " + p.message, c[2], p.length);
            assertTrue(cron + ": " + p.message, p.message.contains((String) c[3]));
        }
    }
}
