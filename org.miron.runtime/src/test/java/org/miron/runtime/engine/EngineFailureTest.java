package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/**
 * Injected failures: the engine keeps the last good configuration, reports on miron.status,
 * drops bad input, and recovers once the fault is gone.
 */
public class EngineFailureTest {
    /** Unprovable pigeonhole (14 into 13 with pairwise !=): Gecode cannot finish within the limit. */
    static final String SLOW = "\narray[1..14] of var 1..13: ph;\n"
            + "constraint forall(i, j in 1..14 where i < j)(ph[i] != ph[j]);\n";
    static final String UNSAT = "\nconstraint task_var != task_var;\n";
    static final String SYNTAX = "\nconstraint this is not minizinc;\n";

    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;
    private String goodModel;

    @Before
    public void setUp() throws Exception {
        f = fixtures.create();
        goodModel = Files.readString(f.mzn);
    }


    private EngineOptions shortLimit() {
        EngineOptions o = f.options();
        o.timeLimitMs = 1500;
        return o;
    }

    @Test
    public void missingMinizincIsAClearStartupError() throws Exception {
        f.startInfrastructure();
        EngineOptions o = f.options();
        o.minizinc = f.dir + "/no/such/minizinc";
        try {
            Engine.create(o).start();
            fail("engine started without minizinc");
        } catch (EngineStartException e) {
            assertTrue(e.getMessage(), e.getMessage().contains(o.minizinc));
            assertTrue(e.getMessage(), e.getMessage().contains("install MiniZinc"));
        }
    }

    @Test
    public void invalidIoJsonIsAClearStartupError() throws Exception {
        Files.writeString(f.ioJson, "{\"format\":1,\"mzn\":\"missing.mzn\"}");
        try {
            Engine.create(f.options());
            fail("engine accepted an io.json naming a missing model");
        } catch (EngineStartException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("missing.mzn"));
        }
    }

    @Test
    public void unknownBackendIsAClearStartupError() throws Exception {
        EngineOptions o = f.options();
        o.backend = "quantum";
        try {
            Engine.create(o);
            fail("engine accepted an unknown backend");
        } catch (EngineStartException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("unknown backend 'quantum' (available: both, minizinc, native)"));
        }
    }

    @Test
    public void nativeBackendOnAFileWithoutDecisionSectionIsAClearStartupError() throws Exception {
        EngineOptions o = f.options(); // testbot.io.json is hand-made for MiniZinc: no decision section
        o.backend = "native";
        try {
            Engine.create(o);
            fail("native backend accepted an io.json without decision section");
        } catch (EngineStartException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("backend native: no 'decision' section")
                    && e.getMessage().contains("--backend minizinc"));
        }
    }

    @Test
    public void timeoutKeepsLastGoodConfiguration() throws Exception {
        f.startInfrastructure().startSkills().startEngine(shortLimit());
        assertNotNull(f.awaitVariant("task", "pickDeliverCharge"));
        f.syncInputs();
        injectAndRecover(() -> Files.writeString(f.mzn, goodModel + SLOW), "TIMEOUT", "timeout");
    }

    @Test
    public void unsatKeepsLastGoodConfiguration() throws Exception {
        f.startAll();
        injectAndRecover(() -> Files.writeString(f.mzn, goodModel + UNSAT), "UNSAT", "unsat");
    }

    @Test
    public void syntaxErrorKeepsLastGoodConfiguration() throws Exception {
        f.startAll();
        injectAndRecover(() -> Files.writeString(f.mzn, goodModel + SYNTAX), "ERROR", "error");
        JsonNode status = f.probe.await(Topics.STATUS, s -> s.path("lastError").path("message").asText()
                .contains("syntax error"), EngineFixture.TIMEOUT);
        assertNotNull("the MiniZinc error message is reported", status);
    }

    /** A wrapper that behaves like minizinc until the file {@code trigger} exists, then runs {@code fault}. */
    private EngineOptions wrapped(String trigger, String fault) throws Exception {
        Path wrapper = f.dir.resolve("minizinc-wrapper.sh");
        Files.writeString(wrapper, "#!/bin/sh\n"
                + "if [ -e \"$(dirname \"$0\")/" + trigger + "\" ]; then " + fault + "; fi\n"
                + "exec minizinc \"$@\"\n");
        Files.setPosixFilePermissions(wrapper, PosixFilePermissions.fromString("rwxr-xr-x"));
        EngineOptions o = shortLimit();
        o.minizinc = wrapper.toString();
        return o;
    }

    @Test
    public void solverCrashKeepsLastGoodConfiguration() throws Exception {
        f.startInfrastructure().startSkills().startEngine(wrapped("crash", "kill -SEGV $$"));
        assertNotNull(f.awaitVariant("task", "pickDeliverCharge"));
        f.syncInputs();
        injectAndRecover(() -> Files.writeString(f.dir.resolve("crash"), ""), "ERROR", "error",
                () -> Files.delete(f.dir.resolve("crash")));
    }

    @Test
    public void hungSolverIsKilledByTheWatchdog() throws Exception {
        // ignores its own time limit: the engine must kill it (and its child) after limit + grace
        f.startInfrastructure().startSkills().startEngine(wrapped("hang", "sleep 120"));
        assertNotNull(f.awaitVariant("task", "pickDeliverCharge"));
        f.syncInputs();
        injectAndRecover(() -> Files.writeString(f.dir.resolve("hang"), ""), "TIMEOUT", "timeout",
                () -> Files.delete(f.dir.resolve("hang")));
        JsonNode killed = f.probe.await(Topics.STATUS, s -> s.path("lastError").path("message").asText()
                .startsWith("minizinc killed after"), EngineFixture.TIMEOUT);
        assertNotNull("the watchdog, not minizinc, ended the solve", killed);
    }

    private interface Io {
        void run() throws Exception;
    }

    private void injectAndRecover(Io inject, String outcome, String kind) throws Exception {
        injectAndRecover(inject, outcome, kind, () -> Files.writeString(f.mzn, goodModel));
    }

    private void injectAndRecover(Io inject, String outcome, String kind, Io repair) throws Exception {
        inject.run();
        f.estimate("power_autonomy", 0.2); // would switch to dock if the solve succeeded
        JsonNode status = f.awaitStatus(s -> s.path("lastOutcome").asText().equals(outcome));
        assertNotNull("miron.status reports " + outcome, status);
        assertEquals("degraded", status.path("state").asText());
        assertEquals(kind, status.path("lastError").path("kind").asText());
        assertEquals("last good configuration kept", "pickDeliverCharge", status.path("applied").path("task").asText());
        assertEquals("pickDeliverCharge", f.engine.applied().get("task").toString().replace("\"", ""));
        assertTrue(f.probe.messages(Topics.VARIANT_PREFIX + "task").stream()
                .allMatch(m -> m.body().path("value").asText().equals("pickDeliverCharge")));
        assertTrue(f.engine.isAlive());

        repair.run();
        f.estimate("power_autonomy", 0.1);
        assertNotNull("engine recovers once the fault is gone", f.awaitVariant("task", "dock"));
    }

    @Test
    public void badInputIsCountedDroppedAndSurvived() throws Exception {
        f.startAll();
        long solves = f.engine.status().get("solves");
        f.publish(Topics.ESTIMATE, "{not json");
        f.publish(Topics.CONTEXT, "[1,2,3]");
        f.publish("roqme.bogus", "{\"name\":\"safety\",\"value\":0.1}");
        f.publish(Topics.ESTIMATE, "{\"name\":\"comfort\",\"namespace\":\"Intralogistics\",\"value\":0.1}");
        f.publish(Topics.OVERRIDE_PREFIX + "nope", "{\"value\":1}");
        f.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"Intralogistics\",\"value\":\"high\"}");
        f.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"Intralogistics\",\"value\":7}");
        f.publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":true}");
        f.publish(Topics.CONTEXT, "{\"name\":\"Space\",\"namespace\":\"Intralogistics\",\"type\":\"enum\",\"value\":\"MEDIUM\"}");
        f.publish(Topics.OVERRIDE_PREFIX + "task", "{\"value\":\"fly\"}");
        f.publish(Topics.ESTIMATE, ""); // no body at all
        JsonNode status = f.awaitStatus(s -> s.path("counters").path("malformedInput").asLong() == 3
                && s.path("counters").path("unknownInput").asLong() == 3
                && s.path("counters").path("badTypeInput").asLong() == 5);
        assertNotNull("all eleven bad messages counted: " + last(f.probe), status);
        assertTrue(f.engine.isAlive());
        assertEquals("no input reached the solver", solves, f.engine.status().get("solves"));
        // still adapting
        f.publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":3.5}");
        assertNotNull(f.awaitVariant("task", "dock"));
    }

    @Test
    public void contextsFeedTheModelOnlyOnceKnown() throws Exception {
        f.startAll();
        // Space LOW caps velocity at 30; before it is known the cap does not apply (55 at start)
        assertTrue(f.skills.awaitChange(c -> c.value() == 55.0, EngineFixture.TIMEOUT).isPresent());
        f.publish(Topics.CONTEXT, "{\"name\":\"Space\",\"namespace\":\"Intralogistics\",\"type\":\"enum\",\"value\":\"LOW\"}");
        assertTrue(f.skills.awaitChange(c -> c.value() == 30.0, EngineFixture.TIMEOUT).isPresent());
        assertFalse(f.engine.status().get("badTypeInput") > 0);
    }

    private static String last(BusProbe probe) {
        var all = probe.messages(Topics.STATUS);
        return all.isEmpty() ? "no status" : all.get(all.size() - 1).body().toString();
    }
}
