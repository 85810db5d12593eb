package org.miron.executor.v4;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.Test;
import org.junit.runner.RunWith;
import org.junit.runners.Parameterized.Parameters;
import org.junit.runners.Parameterized;

/**
 * Our executor against the real BehaviorTree.CPP 4: every scenario in btcpp4/cases runs in both
 * with the same scripted leaf results, and each tick's root status, leaf executions and reported
 * blackboard values must be equal (a tick that fails must fail in both).
 */
@RunWith(Parameterized.class)
public class Btcpp4TickOracleTest {
    private final Path scenario;

    public Btcpp4TickOracleTest(String name, Path scenario) {
        this.scenario = scenario;
    }

    @Parameters(name = "{0}")
    public static List<Object[]> scenarios() throws IOException {
        Path cases = Btcpp4TickOracle.resource("cases");
        try (Stream<Path> files = Files.list(cases)) {
            return files.filter(f -> f.toString().endsWith(".json")).sorted()
                    .map(f -> new Object[] { f.getFileName().toString().replace(".json", ""), f })
                    .collect(Collectors.toList());
        }
    }

    @Test
    public void ticksLikeBehaviorTreeCpp4() throws Exception {
        List<TickRecord> theirs = Btcpp4TickOracle.run(scenario);
        assertFalse("the oracle produced nothing for " + scenario, theirs.isEmpty());
        List<TickRecord> ours = new OurRun(Scenario.read(scenario)).run(scenario);
        assertEquals("tick by tick, BT.CPP 4 (expected) and ours (actual), for " + scenario.getFileName()
                + "\nours: " + ours + "\ntheirs: " + theirs,
                theirs.stream().map(TickRecord::comparable).collect(Collectors.joining("\n")),
                ours.stream().map(TickRecord::comparable).collect(Collectors.joining("\n")));
    }
}
