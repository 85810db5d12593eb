package org.miron.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.generator.cli.MironCli;
import org.miron.runtime.executor.ActionRegistry;
import org.miron.runtime.executor.NodeStatus;
import org.miron.runtime.executor.Tree;
import org.miron.runtime.executor.TreeBuilder;
import org.miron.runtime.executor.TreeContext;
import org.miron.runtime.executor.VariantSource;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The whole chain on the examples: generate, solve the MiniZinc model with the real minizinc as
 * the engine does, publish the decision to the woven tree's VariantAction and run the tree with
 * the BT executor: the robot does what the decision says.
 */
public class GenerateSolveRunTest {
    private static final Path ROOT = Path.of(System.getProperty("miron.root", "..")).toAbsolutePath().normalize();
    private static final ObjectMapper JSON = new ObjectMapper();

    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static Path generate(String example, String model) throws IOException {
        return generateInto(example, example, model);
    }

    private static Path generateInto(String folder, String example, String model) throws IOException {
        Path out = temp.newFolder(folder).toPath();
        int exit = MironCli.run("generate", ROOT.resolve("examples/" + example + "/" + model + ".miron").toString(),
                "-o", out.toString());
        assertEquals(0, exit);
        return out;
    }

    /** The engine's default data (docs/io-json.md) with some values changed. */
    private static ObjectNode data(JsonNode io, Map<String, Object> changes) {
        ObjectNode data = JSON.createObjectNode();
        for (JsonNode in : io.get("inputs")) {
            String param = in.get("param").asText();
            switch (in.get("type").asText()) {
            case "float" -> data.put(param, in.has("initial") ? in.get("initial").asDouble() : 0.0);
            case "bool" -> data.put(param, false);
            default -> data.put(param, 0);
            }
            if (in.has("known")) {
                data.put(in.get("known").asText(), false);
            }
        }
        for (JsonNode vp : io.get("varpoints")) {
            data.put(vp.get("input").asText(), false);
            data.put(vp.get("inputValue").asText(), 0);
            data.put(vp.get("current").asText(), -1);
        }
        changes.forEach((k, v) -> data.set(k, JSON.valueToTree(v)));
        return data;
    }

    /** Runs minizinc as the engine does and returns the label or value chosen per varpoint. */
    private static Map<String, String> solve(Path dir, String model, Map<String, Object> changes)
            throws IOException, InterruptedException {
        JsonNode io = JSON.readTree(dir.resolve(model + ".io.json").toFile());
        Process p = new ProcessBuilder("minizinc", "--solver", "gecode", "--json-stream", "--output-mode", "json",
                "--time-limit", "20000", "-d", io.get("dzn").asText(), "--cmdline-json-data",
                data(io, changes).toString(), io.get("mzn").asText()).directory(dir.toFile()).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        p.getErrorStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        JsonNode solution = null;
        for (String line : out.split("\n")) {
            JsonNode msg = JSON.readTree(line);
            if ("solution".equals(msg.path("type").asText())) {
                solution = msg.get("output").get("json"); // the last one is the best
            }
        }
        assertTrue("no solution: " + out, solution != null);
        Map<String, String> chosen = new java.util.LinkedHashMap<>();
        for (JsonNode vp : io.get("varpoints")) {
            int index = solution.get(vp.get("decision").asText()).asInt();
            chosen.put(vp.get("name").asText(), vp.get("values").get(index).asText());
        }
        return chosen;
    }

    @Test
    public void lowAutonomyMakesTheIntralogisticsRobotDock() throws Exception {
        Path dir = generate("intralogistics", "intralogistics");
        Map<String, String> decision = solve(dir, "intralogistics", Map.of("metric_Intralogistics_power_autonomy", 0.2));
        assertEquals("dock", decision.get("task"));

        List<String> calls = new ArrayList<>();
        ActionRegistry registry = new ActionRegistry();
        registry.registerSync("MoveTo", ports -> {
            calls.add("MoveTo(" + ports.getDouble("x").orElseThrow() + ")");
            return NodeStatus.SUCCESS;
        });
        registry.registerSync("objectpick", ports -> {
            calls.add("objectpick");
            return NodeStatus.SUCCESS;
        });
        registry.registerSync("objectdrop", ports -> {
            calls.add("objectdrop");
            return NodeStatus.SUCCESS;
        });
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        variants.publish("task", decision.get("task"));
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(dir.resolve("intralogistics.ext.xml"));
        assertEquals(NodeStatus.SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        assertEquals("only the Charge variant ran", List.of("MoveTo(-9.33)"), calls);
    }

    @Test
    public void withoutADecisionTheNominalMissionRuns() throws Exception {
        Path dir = generateInto("intralogistics-nominal", "intralogistics", "intralogistics");
        List<String> calls = new ArrayList<>();
        ActionRegistry registry = new ActionRegistry();
        registry.registerSync("MoveTo", ports -> NodeStatus.SUCCESS);
        registry.registerSync("objectpick", ports -> {
            calls.add("objectpick");
            return NodeStatus.SUCCESS;
        });
        registry.registerSync("objectdrop", ports -> {
            calls.add("objectdrop");
            return NodeStatus.SUCCESS;
        });
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        variants.publish("task", solve(dir, "intralogistics", Map.of()).get("task"));
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(dir.resolve("intralogistics.ext.xml"));
        assertEquals(NodeStatus.SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        assertEquals("three picks and drops", 6, calls.size());
    }

    @Test
    public void theCrowdedHospitalCorridorIsCrossedCarefullyAndSlowly() throws Exception {
        Path dir = generate("hospital-delivery", "hospital");
        Map<String, String> decision = solve(dir, "hospital", Map.of("context_Hospital_crowding", 2,
                "context_Hospital_crowding_known", true, "metric_Hospital_comfort", 0.8));
        assertEquals("careful", decision.get("navigation"));
        assertTrue(decision.toString(), Double.parseDouble(decision.get("driveSpeed")) <= 0.3);

        List<String> calls = new ArrayList<>();
        ActionRegistry registry = new ActionRegistry();
        for (String action : List.of("OpenDrawer", "GraspBox", "MoveBase", "RecoveryRotate", "SlowDownSign",
                "CallElevator", "Charge", "Handover", "Speak", "Dispense")) {
            registry.registerSync(action, ports -> {
                calls.add(action);
                return NodeStatus.SUCCESS;
            });
        }
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        for (String enumVarpoint : List.of("navigation", "preparation", "courtesy")) {
            variants.publish(enumVarpoint, decision.get(enumVarpoint));
        }
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(dir.resolve("hospital.ext.xml"));
        assertEquals(NodeStatus.SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        assertTrue(calls.toString(), calls.contains("SlowDownSign"));
        assertTrue(calls.toString(), calls.contains("Handover"));
    }

    @Test
    public void numericDecisionsReachThePortsOfASubtreeWithItsOwnBlackboard() throws Exception {
        Path dir = generateInto("hospital-ports", "hospital-delivery", "hospital");
        // An operator pins navigation to its preset (the nominal Navigate subtree) by the manual override.
        int normal = 0;
        for (JsonNode vp : JSON.readTree(dir.resolve("hospital.io.json").toFile()).get("varpoints")) {
            if (vp.get("name").asText().equals("navigation")) {
                normal = vp.get("preset").asInt();
            }
        }
        Map<String, String> decision = solve(dir, "hospital", Map.of("navigation_input", true,
                "navigation_input_value", normal));
        assertEquals("normal", decision.get("navigation"));

        List<String> moves = new ArrayList<>();
        ActionRegistry registry = new ActionRegistry();
        for (String action : List.of("OpenDrawer", "GraspBox", "RecoveryRotate", "SlowDownSign", "CallElevator",
                "Charge", "Handover", "Speak", "Dispense")) {
            registry.registerSync(action, ports -> NodeStatus.SUCCESS);
        }
        registry.registerSync("MoveBase", ports -> {
            moves.add(ports.getDouble("max_speed").orElse(Double.NaN) + "/" + ports.getDouble("inflation").orElse(Double.NaN));
            return NodeStatus.SUCCESS;
        });
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        for (String enumVarpoint : List.of("navigation", "preparation", "courtesy")) {
            variants.publish(enumVarpoint, decision.get(enumVarpoint));
        }
        // As the live executor does with miron.blackboard.<vp>: numbers into the main tree's blackboard.
        VariantSource numbers = new VariantSource();
        numbers.publish("driveSpeed", Double.parseDouble(decision.get("driveSpeed")));
        numbers.publish("inflation", Double.parseDouble(decision.get("inflation")));
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(dir.resolve("hospital.ext.xml"));
        tree.feedBlackboardFrom(numbers);
        assertEquals(NodeStatus.SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        // The first move is the Navigate subtree's "drive"; ReturnToBase keeps its own literal speed.
        assertEquals(Double.parseDouble(decision.get("driveSpeed")) + "/" + Double.parseDouble(decision.get("inflation")),
                moves.get(0));
    }
}
