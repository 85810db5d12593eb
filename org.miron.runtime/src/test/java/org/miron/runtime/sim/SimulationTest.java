package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.runtime.Json;
import org.miron.testkit.Folders;

/**
 * Closed-loop runs of the intralogistics example in its world: the adaptation reacts to what the
 * world does (low battery: the robot docks and charges; a person close: it slows down), runs are a
 * function of their seed, and the policies differ as the model says they should.
 */
public class SimulationTest {
    private static Path dir;
    private static Setup setup;

    @BeforeClass
    public static void generate() throws Exception {
        dir = Files.createTempDirectory("miron-sim");
        setup = SimFixture.setup("intralogistics", "intralogistics", SimFixture.intralogisticsWorld(), dir);
    }

    @AfterClass
    public static void clean() throws Exception {
        Folders.delete(dir);
    }

    @Test
    public void theSameSeedGivesTheSameRunAndTimeline() {
        Simulation.Result a = new Simulation(setup, Policy.parse("adaptive"), 7, 1_800_000, 1_800_000).run();
        Simulation.Result b = new Simulation(setup, Policy.parse("adaptive"), 7, 1_800_000, 1_800_000).run();
        assertEquals(a.measures(), b.measures());
        assertEquals(a.timeline().size(), b.timeline().size());
        for (int i = 0; i < a.timeline().size(); i++) {
            assertEquals(Json.write(a.timeline().get(i).body()), Json.write(b.timeline().get(i).body()));
            assertEquals(a.timeline().get(i).at(), b.timeline().get(i).at());
        }
        Simulation.Result c = new Simulation(setup, Policy.parse("adaptive"), 8, 1_800_000, 0).run();
        assertTrue("another seed, another run", !a.measures().equals(c.measures()));
    }

    @Test
    public void adaptationSlowsDownNearPeopleAndDocksOnALowBattery() {
        double adaptiveMisses = 0;
        double presetMisses = 0;
        for (long seed = 1; seed <= 3; seed++) {
            Map<String, Double> adaptive = new Simulation(setup, Policy.parse("adaptive"), seed, 2 * 3_600_000L, -1).run().measures();
            Map<String, Double> preset = new Simulation(setup, Policy.parse("preset"), seed, 2 * 3_600_000L, -1).run().measures();
            adaptiveMisses += adaptive.get("near_misses");
            presetMisses += preset.get("near_misses");
            assertTrue(adaptive.get("engine:adaptations") > 0);
            assertEquals(0.0, preset.get("engine:adaptations"), 0);
            assertTrue("the engine slows the robot down near people: " + adaptive + " vs " + preset,
                    adaptive.get("fast_near_person") < preset.get("fast_near_person"));
        }
        // at full speed near a person: 0.1 near misses a second; at the engine's 10 %: 0.001
        assertTrue(adaptiveMisses + " near misses adaptive, " + presetMisses + " preset", adaptiveMisses * 3 < presetMisses);
    }

    @Test
    public void aFixedSlowSpeedIsNeverFastNearAPerson() {
        Map<String, Double> slow = new Simulation(setup, Policy.parse("fixed:maxVelocity=10"), 3, 3_600_000L, -1).run().measures();
        Map<String, Double> fast = new Simulation(setup, Policy.parse("preset"), 3, 3_600_000L, -1).run().measures();
        assertEquals(0.0, slow.get("fast_near_person"), 0);
        assertTrue(fast.get("fast_near_person") > 0);
    }

    @Test
    public void theTimelineShowsTheDecisionsSkillsAndMetrics() {
        Simulation.Result r = new Simulation(setup, Policy.parse("adaptive"), 1, 3 * 3_600_000, 3 * 3_600_000).run();
        List<String> topics = r.timeline().stream().map(TimelineEvent::topic).distinct().toList();
        assertTrue(topics.toString(), topics.containsAll(List.of("roqme.estimate", "roqme.context", "roqme.observation", "miron.decision")));
        assertTrue(r.timeline().stream().anyMatch(e -> e.body().path("name").asText().equals("skill")
                && e.body().path("value").asText().equals("objectdrop")));
        assertTrue(r.timeline().stream().anyMatch(e -> e.topic().equals("miron.decision")
                && e.body().path("decisions").path("task").asText().equals("dock")));
    }

    @Test
    public void anEightHourShiftKeepsNoTimelineUnlessAsked() {
        Simulation.Result r = new Simulation(setup, Policy.parse("adaptive"), 11, 8 * 3_600_000L, -1).run();
        assertTrue(r.measures().toString(), r.measures().get("deliveries") > 0 && r.measures().get("engine:adaptations") > 10);
        assertTrue(r.measures().get("stranded_s") <= 28_800);
        assertTrue(r.measures().get("fast_near_person") >= 0 && r.measures().get("fast_near_person") <= 1);
        assertTrue(r.timeline().isEmpty());
        double safety = r.measures().get("metric:safety");
        assertTrue(safety > 0 && safety < 1);
    }
}
