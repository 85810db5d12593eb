package org.miron.runtime.sim;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Json;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.testkit.JsonSchemaFile;

/**
 * The requirement monitors on the simulator, from a requirements file written as docs/requirements.md
 * documents it (the generator's own output is tested end to end in org.miron.cli): the
 * intralogistics robot under its two policies, over what the README's table already shows.
 */
public class VerificationTest {
    @ClassRule
    public static final TemporaryFolder TMP = new TemporaryFolder();

    private static Setup setup;

    private static synchronized Setup setup() throws Exception {
        if (setup == null) {
            Setup s = SimFixture.setup("intralogistics", "intralogistics", SimFixture.intralogisticsWorld(), TMP.newFolder().toPath());
            setup = new Setup(s.io(), s.roqme(), s.tree(), s.world(), RequirementModel.parse(requirements()));
        }
        return setup;
    }

    /** slowNearPeople, neverStranded and docksOnLowBattery of docs/requirements.md, as the generator writes them. */
    static JsonNode requirements() {
        ObjectNode root = Json.object();
        root.put("format", 1).put("model", "intralogistics");
        ArrayNode s = root.putArray("signals");
        s.add(context("roqme.HumanDistance", "HumanDistance", "number"));
        s.add(context("roqme.BatteryLevel", "BatteryLevel", "number"));
        s.add(context("roqme.Docked", "Docked", "boolean"));
        s.addObject().put("name", "roqme.power_autonomy").put("kind", "property").put("property", "power_autonomy")
                .put("param", "metric_Intralogistics_power_autonomy");
        ObjectNode vel = s.addObject().put("name", "maxVelocity").put("kind", "varpoint").put("varpoint", "maxVelocity")
                .put("type", "number");
        vel.putNull("initial");
        ArrayNode values = vel.putArray("values");
        for (int v = 10; v <= 100; v++) {
            values.add(v);
        }
        ObjectNode task = s.addObject().put("name", "task").put("kind", "varpoint").put("varpoint", "task").put("type", "enum")
                .put("initial", 3);
        task.putArray("values").add("pick").add("deliver").add("dock").add("pickDeliverCharge");
        ArrayNode r = root.putArray("requirements");
        r.add(requirement("slowNearPeople", null, op("always", op("implies",
                state(cmp("<", param("context_Intralogistics_HumanDistance"), 1.5)),
                state(cmp("<=", Json.object().put("value", "maxVelocity"), 10))))));
        r.add(requirement("neverStranded", null, op("never", state(op("and",
                cmp("<", param("context_Intralogistics_BatteryLevel"), 1), op("not", param("context_Intralogistics_Docked")))))));
        ObjectNode dock = op("eventually", state(cmp("=", Json.object().put("index", "task"), 2)));
        dock.put("within", 5000);
        r.add(requirement("docksOnLowBattery", null, op("always", op("implies",
                state(cmp("<", param("metric_Intralogistics_power_autonomy"), 0.3)), dock))));
        r.add(requirement("rarelyStranded", 0.9, op("never", state(op("and",
                cmp("<", param("context_Intralogistics_BatteryLevel"), 1), op("not", param("context_Intralogistics_Docked")))))));
        return root;
    }

    private static ObjectNode context(String name, String context, String type) {
        return Json.object().put("name", name).put("kind", "context").put("context", context).put("roqmeType", type)
                .put("param", "context_Intralogistics_" + context);
    }

    private static ObjectNode requirement(String name, Double p, JsonNode formula) {
        ObjectNode o = Json.object().put("name", name).put("line", 1).put("column", 1).put("text", name);
        if (p == null) {
            o.putNull("probability");
        } else {
            o.put("probability", p);
        }
        o.putArray("reads");
        o.set("formula", formula);
        return o;
    }

    private static ObjectNode state(JsonNode e) {
        ObjectNode o = Json.object();
        o.set("state", e);
        o.putArray("reads");
        return o;
    }

    private static ObjectNode param(String p) {
        return Json.object().put("param", p);
    }

    private static ObjectNode cmp(String op, JsonNode a, double c) {
        return op(op, a, Json.object().put("const", c));
    }

    private static ObjectNode op(String op, JsonNode... args) {
        ObjectNode o = Json.object().put("op", op);
        ArrayNode a = o.putArray("args");
        for (JsonNode x : args) {
            a.add(x);
        }
        return o;
    }

    private static Verification.Options fixed(int runs) {
        return new Verification.Options(runs, 0, 0.95, 0.05, 1, 3 * 3_600_000, 2);
    }

    @Test
    public void theAdaptiveRobotNeverStrandsThePresetOneDoesAndSlowsDownOnlyAfterAPersonIsNear() throws Exception {
        List<Verification.PolicyResult> r = Verification.run(setup(), List.of(Policy.parse("adaptive"), Policy.parse("preset")),
                fixed(3));
        Map<String, Verification.Check> adaptive = checks(r.get(0));
        Map<String, Verification.Check> preset = checks(r.get(1));
        assertEquals("holds", adaptive.get("neverStranded").verdict());
        assertEquals("holds", adaptive.get("docksOnLowBattery").verdict());
        assertEquals("violated", preset.get("neverStranded").verdict());
        // the adaptation's lag: the engine slows down once safety has dropped, not as the person comes near
        Verification.Check lag = adaptive.get("slowNearPeople");
        assertEquals("violated", lag.verdict());
        Verification.Counterexample x = lag.first();
        assertNotNull(x);
        assertTrue(x.values().toString(), ((Double) x.values().get("roqme.HumanDistance")) < 1.5);
        assertTrue(x.values().toString(), ((Number) x.values().get("maxVelocity")).doubleValue() > 10);
        // the preset robot strands: its first counterexample is when the battery runs out away from the dock
        Verification.Counterexample stranded = preset.get("neverStranded").first();
        assertTrue(stranded.values().toString(), ((Double) stranded.values().get("roqme.BatteryLevel")) < 1);
        assertEquals(false, stranded.values().get("roqme.Docked"));
        assertEquals(3, preset.get("neverStranded").violated());
        assertEquals(0, preset.get("neverStranded").interval().hi() == 1.0 ? 0 : 1);
    }

    @Test
    public void theSequentialTestDecidesAProbabilisticRequirementAndTheSameSeedGivesTheSameSummary() throws Exception {
        Verification.Options o = new Verification.Options(0, 200, 0.95, 0.05, 1, 3 * 3_600_000, 2);
        List<Verification.PolicyResult> preset = Verification.run(setup(), List.of(Policy.parse("preset")), o);
        Verification.Check stranded = checks(preset.get(0)).get("rarelyStranded");
        assertEquals("fails", stranded.verdict());
        // every preset run strands (the README's table): ln(19) / ln(0.15 / 0.05) = 2.7, so 3 runs decide
        assertEquals(3, stranded.runs());
        String first = Json.MAPPER.writeValueAsString(Verification.summary(preset, o));
        String again = Json.MAPPER.writeValueAsString(Verification.summary(Verification.run(setup(),
                List.of(Policy.parse("preset")), new Verification.Options(0, 200, 0.95, 0.05, 1, 3 * 3_600_000, 1)), o));
        assertEquals(first, again);
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(Json.MAPPER.readTree(first)));
        List<Verification.PolicyResult> both = Verification.run(setup(), List.of(Policy.parse("adaptive"), Policy.parse("preset")), fixed(2));
        assertEquals(List.of(), JsonSchemaFile.VERIFY_SUMMARY.problems(Verification.summary(both, fixed(2))));
    }

    private static Map<String, Verification.Check> checks(Verification.PolicyResult r) {
        Map<String, Verification.Check> m = new java.util.LinkedHashMap<>();
        r.checks().forEach(c -> m.put(c.requirement().name(), c));
        return m;
    }
}
