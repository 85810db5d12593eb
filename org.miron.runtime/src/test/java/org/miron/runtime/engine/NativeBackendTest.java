package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The native backend's semantics on a small hand-written decision section (the differential test
 * in the tests module compares it with MiniZinc on random generated models).
 * Model: speed in {0, 0.5, 1, 1.5} (utility for safety falling, for time rising), mode enum
 * {eco, normal (preset), fast} without impacts; rules: a known crowded context caps speed at 0.5;
 * safety below 0.3 makes speed = 0.2 (within half a step: 0); mode fast needs speed >= 1 (coupling).
 */
public class NativeBackendTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final String IO = """
            {"format": 1, "mzn": "m.mzn", "weights": "need",
             "inputs": [
               {"kind": "metric", "name": "safety", "param": "metric_safety", "type": "float", "initial": 0.5},
               {"kind": "metric", "name": "time", "param": "metric_time", "type": "float", "initial": 0.5},
               {"kind": "context", "name": "crowded", "roqmeType": "boolean", "param": "context_crowded",
                "type": "bool", "known": "context_crowded_known"}],
             "varpoints": [
               {"name": "speed", "kind": "number", "values": [0, 0.5, 1, 1.5], "preset": null, "decision": "speed_var",
                "input": "speed_input", "inputValue": "speed_input_value", "current": "speed_current", "binding": null},
               {"name": "mode", "kind": "enum", "values": ["eco", "normal", "fast"], "preset": 1, "decision": "mode_var",
                "input": "mode_input", "inputValue": "mode_input_value", "current": "mode_current", "binding": null}],
             "decision": {"objective": "maximize",
               "varpoints": [
                 {"name": "speed", "utilities": [
                   {"metric": "metric_safety", "table": [100.0, 75.0, 50.0, 25.0]},
                   {"metric": "metric_time", "table": [0.0, 25.0, 50.0, 75.0]}]},
                 {"name": "mode", "utilities": []}],
               "rules": [
                 {"name": "crowd", "known": ["context_crowded_known"], "condition": {"param": "context_crowded"},
                  "consequences": [{"overrides": ["speed"],
                    "constraint": {"op": "<=", "args": [{"value": "speed"}, {"const": 0.5}]}}]},
                 {"name": "unsafe", "known": [], "condition": {"op": "<", "args": [{"param": "metric_safety"}, {"const": 0.3}]},
                  "consequences": [{"overrides": ["speed"], "constraint": {"op": "<=", "args": [
                    {"op": "abs", "args": [{"op": "-", "args": [{"value": "speed"}, {"const": 0.2}]}]}, {"const": 0.25}]}}]},
                 {"name": "fast", "known": [], "condition": {"op": "=", "args": [{"index": "mode"}, {"const": 2}]},
                  "consequences": [{"overrides": ["speed"],
                    "constraint": {"op": ">=", "args": [{"value": "speed"}, {"const": 1}]}}]}]}}
            """;

    private NativeBackend backend(String io) throws IOException {
        return new NativeBackend(model(io));
    }

    private IoModel model(String io) throws IOException {
        Path dir = temp.newFolder().toPath();
        Files.writeString(dir.resolve("m.mzn"), "% unused by the native backend\n");
        Files.writeString(dir.resolve("m.io.json"), io);
        return IoModel.load(dir.resolve("m.io.json"));
    }

    private static String withoutDecision() {
        return IO.substring(0, IO.indexOf(",\n \"decision\"")) + "}";
    }

    @Test
    public void nativeIsTheDefaultUnlessTheFileHasNoDecisionSection() throws Exception {
        EngineOptions o = new EngineOptions(null);
        assertEquals("native", Backends.create(o.backend, model(IO), o).name());
        assertEquals("minizinc", Backends.create(o.backend, model(withoutDecision()), o).name());
        assertEquals("both", Backends.create("both", model(IO), o).name());
    }

    private static Map<String, Object> inputs(Object... changes) {
        Map<String, Object> p = new LinkedHashMap<>(Map.of("metric_safety", 0.5, "metric_time", 0.5,
                "context_crowded", false, "context_crowded_known", false, "speed_input", false,
                "speed_input_value", 0, "speed_current", -1, "mode_input", false, "mode_input_value", 0,
                "mode_current", -1));
        for (int i = 0; i < changes.length; i += 2) {
            p.put((String) changes[i], changes[i + 1]);
        }
        return p;
    }

    private static Map<String, Integer> decided(SolveResult r) {
        assertTrue(r.status() + " " + r.message(), r.solved());
        return r.decisions();
    }

    @Test
    public void theBestWeightedUtilityWinsThenThePresetThenTheCurrentValue() throws IOException {
        NativeBackend b = backend(IO);
        // safety 0.5, time 0.5: every speed has gain 50; ties go to the lowest index, mode to its preset
        assertEquals(Map.of("speed_var", 0, "mode_var", 1), decided(b.solve(inputs())));
        assertEquals(Map.of("speed_var", 2, "mode_var", 1), decided(b.solve(inputs("speed_current", 2))));
        // time matters more (need 0.9): the fastest speed
        assertEquals(3, (int) decided(b.solve(inputs("metric_time", 0.1))).get("speed_var"));
        assertEquals(0, (int) decided(b.solve(inputs("metric_safety", 0.35))).get("speed_var"));
    }

    @Test
    public void rulesFireOnlyOnKnownContextsAndYieldToOverrides() throws IOException {
        NativeBackend b = backend(IO);
        Object[] fast = {"metric_time", 0.1};
        assertEquals(3, (int) decided(b.solve(inputs(fast[0], fast[1], "context_crowded", true))).get("speed_var"));
        assertEquals(1, (int) decided(b.solve(inputs(fast[0], fast[1], "context_crowded", true,
                "context_crowded_known", true))).get("speed_var"));
        assertEquals(3, (int) decided(b.solve(inputs(fast[0], fast[1], "context_crowded", true,
                "context_crowded_known", true, "speed_input", true, "speed_input_value", 3))).get("speed_var"));
    }

    @Test
    public void numericEqualityIsWithinHalfAStep() throws IOException {
        // speed = 0.2 within 0.25: only 0 qualifies although 0.5 has the better gain
        assertEquals(0, (int) decided(backend(IO).solve(inputs("metric_safety", 0.2, "metric_time", 0.0)))
                .get("speed_var"));
    }

    @Test
    public void coupledVarpointsAreSearchedTogether() throws IOException {
        NativeBackend b = backend(IO);
        // mode pinned to fast forces speed >= 1 even when safety wants it slow
        assertEquals(Map.of("speed_var", 2, "mode_var", 2),
                decided(b.solve(inputs("metric_safety", 0.4, "mode_input", true, "mode_input_value", 2))));
        // fast and unsafe together: no speed is both >= 1 and near 0.2
        SolveResult r = b.solve(inputs("metric_safety", 0.2, "mode_input", true, "mode_input_value", 2));
        assertEquals(SolveResult.Status.UNSAT, r.status());
        assertEquals("model is unsatisfiable", r.message());
    }

    @Test
    public void anOverrideOutsideTheValuesIsUnsatAndAMissingParameterAnError() throws IOException {
        NativeBackend b = backend(IO);
        assertEquals(SolveResult.Status.UNSAT, b.solve(inputs("speed_input", true, "speed_input_value", 4)).status());
        Map<String, Object> p = inputs();
        p.remove("metric_time");
        assertEquals(SolveResult.Status.ERROR, b.solve(p).status());
    }

    @Test
    public void withoutImpactsThePresetThenTheCurrentValueIsTried() throws IOException {
        NativeBackend b = backend(IO.replace("\"maximize\"", "\"satisfy\""));
        assertEquals(Map.of("speed_var", 0, "mode_var", 1), decided(b.solve(inputs())));
        assertEquals(Map.of("speed_var", 3, "mode_var", 1), decided(b.solve(inputs("speed_current", 3))));
    }

    @Test
    public void aFileWithoutDecisionSectionIsRefusedWithAHint() throws IOException {
        try {
            backend(withoutDecision());
            fail("accepted an io.json without decision section");
        } catch (IllegalArgumentException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("--backend minizinc"));
        }
    }

    @Test
    public void roundingIsHalfAwayFromZeroAsMiniZinc() {
        assertEquals(3, NativeBackend.round(2.5));
        assertEquals(2, NativeBackend.round(2.4999));
        assertEquals(-3, NativeBackend.round(-2.5));
    }

    @Test
    public void bothUsesTheReferenceAndCountsDisagreements() throws IOException {
        NativeBackend nat = backend(IO);
        SolverBackend constant = new SolverBackend() {
            @Override
            public String name() {
                return "reference";
            }

            @Override
            public void check() {
            }

            @Override
            public SolveResult solve(Map<String, Object> params) {
                return new SolveResult(SolveResult.Status.SOLVED, Map.of("speed_var", 0, "mode_var", 1), true, "", 0);
            }
        };
        CrossCheckBackend both = new CrossCheckBackend(constant, nat);
        assertEquals(Map.of("speed_var", 0, "mode_var", 1), decided(both.solve(inputs())));
        assertEquals(0L, (long) both.counters().get("disagreements"));
        assertEquals(Map.of("speed_var", 0, "mode_var", 1), decided(both.solve(inputs("metric_time", 0.1))));
        assertEquals(1L, (long) both.counters().get("disagreements"));
    }

    /**
     * The hot path allocates nothing: once warm, repeated solves on changing inputs that keep the
     * decision (the engine's steady state) allocate no byte on the calling thread.
     */
    @Test
    public void aSolveThatKeepsTheDecisionAllocatesNothing() throws IOException {
        NativeBackend b = backend(IO);
        Map<String, Object> safe = inputs("metric_safety", 0.9, "context_crowded", true, "context_crowded_known", true);
        Map<String, Object> safer = inputs("metric_safety", 0.95, "context_crowded", true, "context_crowded_known", true);
        Map<String, Integer> first = decided(b.solve(safe));
        for (int i = 0; i < 20_000; i++) { // warm-up: compiled code, the cached result
            b.solve(i % 2 == 0 ? safe : safer);
        }
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long before = threads.getCurrentThreadAllocatedBytes();
        SolveResult r = null;
        for (int i = 0; i < 1000; i++) {
            r = b.solve(i % 2 == 0 ? safe : safer);
        }
        long allocated = threads.getCurrentThreadAllocatedBytes() - before;
        assertEquals(first, decided(r));
        // A new result per solve would be >= 150 KB; a solve that happens to take a whole millisecond
        // (a GC pause under load) gets a new result too: a few of those stay far below 16 KB.
        assertTrue(allocated + " bytes allocated by 1000 solves", allocated < 16_384);
    }
}
