package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.Test;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;
import org.miron.runtime.roqme.model.RoqmeModel;

/** The world's semantics: durations, effects per second and at the end, events, random processes under a seed. */
public class WorldTest {
    private static final WorldEnv ENV = new WorldEnv(Map.of("MoveTo", Set.of("x", "y"), "Go", Set.of("goal"), "Pick", Set.of()),
            Map.of("Battery", new RoqmeModel.Type("number", null, null, null, null, null)));

    private static final String WORLD = """
            {
              "places": { "dock": { "x": 0, "y": 0 }, "shelf": { "x": 30, "y": 40 }, "far": { "x": 100, "y": 0 } },
              "distances": [ { "from": "dock", "to": "far", "m": 150 } ],
              "start": "dock",
              "state": {
                "battery": { "type": "number", "initial": 50, "min": 0, "max": 100 },
                "docked": { "type": "boolean", "initial": true },
                "carrying": { "type": "boolean", "initial": false },
                "visitors": { "type": "number", "initial": 0 }
              },
              "parameters": { "speed": 2 },
              "events": ["Picked", "Dropped", "Visit"],
              "skills": {
                "MoveTo": { "target": { "x": "x", "y": "y" }, "requires": "battery > 0", "duration": "distance / speed",
                            "start": "docked = false", "perSecond": { "battery": "-0.5 * speed" }, "end": "docked = place == 'dock'" },
                "Go": { "target": "goal", "duration": "distance / speed" },
                "Pick": { "duration": "4", "end": "carrying = true", "events": ["Picked"],
                          "outcomes": [ { "probability": "place != 'shelf'", "result": "ERROR", "events": ["Dropped"] } ] }
              },
              "processes": {
                "charging": { "while": "docked", "perSecond": { "battery": "2" } },
                "visits": { "rate": "0.5", "do": "visitors += 1", "events": ["Visit"] },
                "census": { "every": "10s", "do": "visitors = visitors * 1" }
              },
              "contexts": { "Battery": { "value": "battery" } },
              "measures": { "visits": { "count": "Visit" } }
            }
            """;

    private static WorldModel model() throws Exception {
        return WorldReader.read(WORLD, "world.json", ENV);
    }

    /** Runs the world until {@code t}, instant by instant, and returns the events it emitted. */
    private static List<String> runUntil(World w, long t) {
        List<String> events = new ArrayList<>();
        while (w.nextEvent() <= t) {
            w.advance(w.nextEvent());
            w.fire();
            events.addAll(w.takeEvents());
        }
        w.advance(t);
        return events;
    }

    @Test
    public void aMoveTakesDistanceOverSpeedAndDrainsPerSecond() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        SkillHandle move = w.push(new SkillRequest("MoveTo", Map.of("x", 30.0, "y", 40.0)));
        assertEquals("the start effect undocks at once (booleans are 1/0 once a script wrote them)", 0L, w.value("docked"));
        runUntil(w, 24_999);
        assertFalse("50 m at 2 m/s take 25 s", move.result().isDone());
        runUntil(w, 25_000);
        assertEquals(SkillResult.Outcome.SUCCESS, move.result().getNow(null).outcome());
        // 25 s at -1 %/s (no charging once undocked), the start effect first
        assertEquals(25.0, ((Number) w.value("battery")).doubleValue(), 1e-9);
        SkillHandle back = w.push(new SkillRequest("Go", Map.of("goal", "dock")));
        runUntil(w, 50_000);
        assertEquals(SkillResult.Outcome.SUCCESS, back.result().getNow(null).outcome());
    }

    @Test
    public void aSpeedChangeMidMoveLengthensTheRestOfTheMoveOnly() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        SkillHandle move = w.push(new SkillRequest("MoveTo", Map.of("x", 30.0, "y", 40.0)));
        runUntil(w, 10_000); // 50 m at 2 m/s: 20 m done, 30 m to go
        w.setParameter("speed", 1.0);
        runUntil(w, 39_999);
        assertFalse("the 30 m left at 1 m/s take 30 s more", move.result().isDone());
        runUntil(w, 40_000);
        assertEquals(SkillResult.Outcome.SUCCESS, move.result().getNow(null).outcome());
        // 10 s at -1 %/s, then 30 s at -0.5 %/s: the drain follows the speed too
        assertEquals(25.0, ((Number) w.value("battery")).doubleValue(), 1e-9);

        // A skill whose duration does not read the parameter ends when it would have; the same value again changes nothing.
        SkillHandle pick = w.push(new SkillRequest("Pick", Map.of()));
        runUntil(w, 42_000);
        w.setParameter("speed", 3.0);
        w.setParameter("speed", 3);
        runUntil(w, 43_999);
        assertFalse(pick.result().isDone());
        runUntil(w, 44_000);
        assertTrue(pick.result().isDone());
    }

    @Test
    public void pathLengthsReplaceTheStraightLineAndUnknownPlacesFail() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        SkillHandle go = w.push(new SkillRequest("Go", Map.of("goal", "far")));
        runUntil(w, 74_999);
        assertFalse("150 m of path at 2 m/s, not the 100 m straight line", go.result().isDone());
        runUntil(w, 75_000);
        assertTrue(go.result().isDone());
        SkillHandle lost = w.push(new SkillRequest("Go", Map.of("goal", "nowhere")));
        runUntil(w, 75_000);
        assertEquals(SkillResult.Outcome.ERROR, lost.result().getNow(null).outcome());
        assertTrue(w.problems().toString(), w.problems().get(0).contains("'nowhere', which is no place"));
    }

    @Test
    public void chargingWhileDockedIsClampedAtTheMaximum() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        runUntil(w, 10_000);
        assertEquals(70.0, ((Number) w.value("battery")).doubleValue(), 1e-9);
        runUntil(w, 100_000);
        assertEquals(100.0, ((Number) w.value("battery")).doubleValue(), 1e-9);
    }

    @Test
    public void endEffectsEventsAndOutcomes() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        SkillHandle pick = w.push(new SkillRequest("Pick", Map.of()));
        List<String> events = runUntil(w, 4_000);
        assertEquals("not at the shelf: the ERROR outcome", SkillResult.Outcome.ERROR, pick.result().getNow(null).outcome());
        assertTrue(events.contains("Dropped"));
        assertFalse(events.contains("Picked"));
        w.push(new SkillRequest("MoveTo", Map.of("x", 30.0, "y", 40.0)));
        runUntil(w, 40_000);
        SkillHandle again = w.push(new SkillRequest("Pick", Map.of()));
        events = runUntil(w, 44_000);
        assertEquals(SkillResult.Outcome.SUCCESS, again.result().getNow(null).outcome());
        assertTrue(events.contains("Picked"));
        assertEquals(1L, w.value("carrying"));
    }

    @Test
    public void aRequirementThatFailsStopsTheSkill() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        SkillHandle far = w.push(new SkillRequest("MoveTo", Map.of("x", 1000.0, "y", 0.0)));
        runUntil(w, 60_000);
        // 50 % at -1 %/s: empty after 50 s; the move fails at the next instant after that
        assertEquals(SkillResult.Outcome.ERROR, far.result().getNow(null).outcome());
        SkillHandle stuck = w.push(new SkillRequest("MoveTo", Map.of("x", 0.0, "y", 0.0)));
        runUntil(w, 60_000);
        assertEquals(SkillResult.Outcome.ERROR, stuck.result().getNow(null).outcome());
    }

    @Test
    public void randomProcessesFollowTheirRateAndTheSeed() throws Exception {
        World a = new World(model(), 42);
        a.start(0);
        long visits = runUntil(a, 2_000_000).stream().filter("Visit"::equals).count();
        // Poisson, 0.5/s over 2000 s: mean 1000, standard deviation 31.6; 5 deviations either side
        assertTrue("visits: " + visits, Math.abs(visits - 1000) < 160);
        World b = new World(model(), 42);
        b.start(0);
        assertEquals(visits, runUntil(b, 2_000_000).stream().filter("Visit"::equals).count());
        World c = new World(model(), 43);
        c.start(0);
        assertTrue(runUntil(c, 2_000_000).stream().filter("Visit"::equals).count() != visits);
    }

    @Test
    public void abortingASkillLeavesItsEndEffectsUndone() throws Exception {
        World w = new World(model(), 1);
        w.start(0);
        w.push(new SkillRequest("MoveTo", Map.of("x", 30.0, "y", 40.0)));
        SkillHandle pick = w.push(new SkillRequest("Pick", Map.of()));
        runUntil(w, 1_000);
        pick.abort();
        assertEquals(SkillResult.Outcome.ABORT, pick.result().getNow(null).outcome());
        runUntil(w, 10_000);
        assertEquals(Boolean.FALSE, w.value("carrying"));
    }
}
