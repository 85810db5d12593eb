package org.miron.runtime.faults;

import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.Rule;
import org.junit.Test;
import org.miron.runtime.engine.EngineOptions;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.EngineFixtures;

/**
 * Issue 10, item 3: after a solver crash the engine keeps the last configuration and solves the
 * same inputs again with back-off, without any input being republished.
 */
public class SolverRetryTest {
    @Rule
    public final EngineFixtures fixtures = new EngineFixtures();
    private EngineFixture f;

    @Test
    public void aCrashedSolveIsRetriedOnUnchangedInputsUntilItSucceeds() throws Exception {
        f = fixtures.create();
        // minizinc that crashes while the file "crash" exists
        Path wrapper = f.dir.resolve("minizinc-wrapper.sh");
        Files.writeString(wrapper, "#!/bin/sh\nif [ -e \"$(dirname \"$0\")/crash\" ]; then kill -SEGV $$; fi\n"
                + "exec minizinc \"$@\"\n");
        Files.setPosixFilePermissions(wrapper, PosixFilePermissions.fromString("rwxr-xr-x"));
        EngineOptions o = f.options();
        o.minizinc = wrapper.toString();
        o.solveRetryMinMs = 200;
        o.solveRetryMaxMs = 800;
        f.startInfrastructure().startSkills().startEngine(o);
        assertNotNull(f.awaitVariant("task", "pickDeliverCharge"));
        f.syncInputs();

        Path crash = Files.writeString(f.dir.resolve("crash"), "");
        f.estimate("power_autonomy", 0.2);
        assertNotNull("the crash is reported", f.awaitStatus(s -> s.path("lastOutcome").asText().equals("ERROR")));
        assertNotNull("and retried while it lasts", f.awaitStatus(s -> s.path("counters").path("solveRetries").asLong() >= 2
                && s.path("lastOutcome").asText().equals("ERROR")));
        Files.delete(crash);
        // no input is republished: the retry alone must bring the decision
        assertNotNull("the retry solves the unchanged inputs", f.awaitVariant("task", "dock"));
        assertTrue(f.engine.isAlive());
    }
}
