package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;

import java.util.HashMap;
import java.util.Map;
import org.junit.Test;

/** The worked example of the reasoner (shared/spec/roqme-runtime.md), replayed from a trace: the table to 1e-6. */
public class WorkedExampleTest {
    private static final Object[][] TABLE = {
        {1, "near", 0.333333, 0.800000},
        {2, "near", 0.205043, 0.800000},
        {3, "", 0.215140, 0.800000},
        {4, "", 0.225055, 0.800000},
        {5, "open", 0.505603, 0.800000},
        {6, "low", 0.483393, 0.145455},
        {7, "", 0.465957, 0.152967},
        {8, "", 0.452151, 0.160392},
        {30, "", 0.423008, 0.303834},
        {60, "", 0.472675, 0.449058},
        {61, "", 0.473817, 0.453086},
    };

    @Test
    public void tableMatchesTheSpec() throws Exception {
        String csv = RoqmeFixtures.replay(RoqmeFixtures.compile(RoqmeFixtures.resource("worked.roqme.json")),
                RoqmeFixtures.resource("worked.trace.jsonl"), 1000, 61L);
        String[] lines = csv.split("\n");
        assertEquals("tick,time,safety,autonomy,fired", lines[0]);
        assertEquals(62, lines.length);
        Map<Integer, String[]> rows = new HashMap<>();
        for (int i = 1; i < lines.length; i++) {
            String[] f = lines[i].split(",", -1);
            rows.put(Integer.parseInt(f[0]), f);
        }
        for (Object[] row : TABLE) {
            String[] f = rows.get((Integer) row[0]);
            assertEquals("tick " + row[0] + " time", (Integer) row[0] * 1000.0, Double.parseDouble(f[1]), 0);
            assertEquals("tick " + row[0] + " fired", row[1], f[4]);
            assertEquals("tick " + row[0] + " safety", (double) row[2], Double.parseDouble(f[2]), 1e-6);
            assertEquals("tick " + row[0] + " autonomy", (double) row[3], Double.parseDouble(f[3]), 1e-6);
        }
    }
}
