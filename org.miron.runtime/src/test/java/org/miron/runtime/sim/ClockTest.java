package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.testkit.Folders;

/**
 * The virtual clock against the wall clock on a short run without randomness: a person comes close
 * at 3 s and leaves at 9 s, the battery falls below LowBattery at about 6 s. Both clocks must take
 * the same decisions in the same order (their times differ by the machine's delays).
 */
public class ClockTest {
    private static final String WORLD = """
            {
              "places": { "dock": { "x": -9.33, "y": 2.17 }, "dropzone": { "x": -8.08, "y": 4.11 }, "shelf": { "x": -2.50, "y": 6.40 } },
              "distances": [ { "from": "dock", "to": "shelf", "m": 60 } ],
              "start": "dock",
              "state": {
                "battery": { "type": "number", "initial": 36, "min": 0, "max": 100 },
                "docked": { "type": "boolean", "initial": true },
                "humanDistance": { "type": "number", "initial": 8, "min": 0 }
              },
              "parameters": { "transvel": 100 },
              "events": ["DeliveryDone"],
              "skills": {
                "MoveTo": { "target": { "x": "x", "y": "y" }, "duration": "2 + distance / (transvel / 100)", "start": "docked = false",
                            "perSecond": { "battery": "-1" }, "end": "docked = place == 'dock'" },
                "objectpick": { "duration": "3" },
                "objectdrop": { "duration": "3", "events": ["DeliveryDone"] }
              },
              "processes": {
                "personComes": { "every": "3s", "do": "humanDistance = time >= 2.5 && time < 8.5 ? 1.0 : 8" }
              },
              "contexts": {
                "BatteryLevel": { "value": "battery", "every": "1s" },
                "HumanDistance": { "value": "humanDistance", "every": "500ms" },
                "Docked": { "value": "docked" },
                "DeliveryDone": { "event": "DeliveryDone" }
              },
              "measures": { "deliveries": { "count": "DeliveryDone" } }
            }
            """;

    private static Path dir;
    private static Setup setup;

    @BeforeClass
    public static void generate() throws Exception {
        dir = Files.createTempDirectory("miron-clock");
        Path world = Files.writeString(dir.resolve("world.json"), WORLD);
        setup = SimFixture.setup("intralogistics", "intralogistics", world, dir.resolve("model"));
    }

    @AfterClass
    public static void clean() throws Exception {
        Folders.delete(dir);
    }

    /** The decisions of a run: each changed varpoint with its new value, in order. */
    private static List<String> decisions(Simulation.Result r) {
        return r.timeline().stream().filter(e -> e.topic().equals("miron.decision"))
                .flatMap(e -> java.util.stream.StreamSupport.stream(e.body().path("changed").spliterator(), false)
                        .map(vp -> vp.asText() + "=" + e.body().path("decisions").path(vp.asText()).asText()))
                .toList();
    }

    @Test
    public void theWallClockTakesTheSameDecisionsAsTheVirtualOne() {
        Simulation.Result virtual = new Simulation(setup, Policy.parse("adaptive"), 1, 20_000, 20_000).run();
        Simulation.Result real = new Simulation(setup, Policy.parse("adaptive"), 1, 20_000, 20_000).realTime(1).run();
        List<String> expected = decisions(virtual);
        assertTrue("the run must adapt to the person and the battery: " + expected,
                expected.contains("maxVelocity=10") && expected.contains("task=dock"));
        assertEquals(expected, decisions(real));
    }
}
