package org.miron.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.executor.ActionRegistry;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.engine.InputState;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.MiniZincBackend;
import org.miron.runtime.engine.SolveResult;
import org.miron.runtime.engine.VariationPoint;
import org.miron.testkit.RepositoryRoot;


/**
 * The whole chain on the examples: generate, solve the MiniZinc model with the engine's own
 * minizinc backend, publish the decision to the woven tree's VariantAction and run the tree with
 * the BT executor: the robot does what the decision says.
 */
public class GenerateSolveRunTest {
    private static final Path ROOT = RepositoryRoot.path();

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

    /**
     * Solves the generated model as the engine does: its own minizinc backend, from its initial
     * inputs (metrics at their reference, contexts unknown, no override) with some values changed.
     * Returns the label or value chosen per varpoint.
     */
    private static Map<String, String> solve(Path dir, String model, Map<String, Object> changes) throws Exception {
        IoModel io = IoModel.load(dir.resolve(model + ".io.json"));
        Map<String, Object> params = new java.util.LinkedHashMap<>(new InputState(io).snapshot().params());
        params.putAll(changes);
        try (MiniZincBackend backend = new MiniZincBackend(io, "minizinc", "gecode", 20_000)) {
            SolveResult result = backend.solve(params);
            assertTrue(result.status() + ": " + result.message(), result.solved());
            Map<String, String> chosen = new java.util.LinkedHashMap<>();
            for (VariationPoint vp : io.varpoints()) {
                chosen.put(vp.name(), vp.values().get(result.decisions().get(vp.decision())).asText());
            }
            return chosen;
        }
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
        int normal = IoModel.load(dir.resolve("hospital.io.json")).varpoint("navigation").orElseThrow().preset();
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
