package org.miron.tests.btcpp;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.executor.ActionRegistry;
import org.miron.executor.AsyncAction;
import org.miron.executor.AsyncActionNode;
import org.miron.executor.NodeStatus;
import org.miron.executor.Ports;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.executor.scripting.ScriptValues;
import org.miron.executor.skills.VariantSource;
import org.miron.runtime.Json;

/**
 * The woven examples (v4 weaving) tick by tick on both executors, with scripted action results
 * and the engine's decisions changing at given ticks: the real BehaviorTree.CPP 4.8.2 with the
 * MIRoN plugin (miron-btcpp-run --script) and the Java executor must give, at every tick, the
 * same root status, the same leaf executions in the same order (starts, runs, halts) and the same
 * VariantAction outputs on the blackboard.
 */
public class TickEqualityTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();
    private static Path woven;

    @BeforeClass
    public static void weave() throws Exception {
        BtcppRunner.assumeBuilt();
        woven = temp.newFolder("woven").toPath();
        for (String model : List.of("intralogistics/intralogistics.miron", "hospital-delivery/hospital.miron")) {
            BtcppRunner.weaveV4(woven, model);
        }
    }

    @Test
    public void intralogisticsTicksAlike() throws Exception {
        ObjectNode s = scenario("intralogistics.ext.xml", 24, List.of("task_sel"));
        actions(s, Map.of("MoveTo", List.of("RUNNING", "RUNNING", "SUCCESS", "RUNNING", "SUCCESS", "SUCCESS", "RUNNING"),
                "objectpick", List.of("FAILURE", "RUNNING", "SUCCESS"),
                "objectdrop", List.of("RUNNING", "SUCCESS", "FAILURE", "SUCCESS")));
        variants(s, 1, Map.of("task", "pick"));
        variants(s, 5, Map.of("task", "deliver"));
        variants(s, 9, Map.of("task", "dock"));   // switches branch while a skill runs: it is halted
        variants(s, 13, Map.of("task", "pick"));
        variants(s, 20, Map.of("task", "nonsense")); // no case matches: the default branch
        assertSameTicks(s);
    }

    @Test
    public void hospitalTicksAlike() throws Exception {
        // several missions: the mission sets {ward} with SetBlackboard each time (the plugin's string
        // ports keep BehaviorTree.CPP 4.8.2 from emptying it, and from throwing the second time)
        ObjectNode s = scenario("hospital.ext.xml", 24, List.of("navigation_sel", "preparation_sel", "courtesy_sel", "ward"));
        actions(s, Map.of("MoveBase", List.of("RUNNING", "SUCCESS", "RUNNING", "RUNNING", "SUCCESS", "FAILURE", "SUCCESS"),
                "Charge", List.of("RUNNING", "SUCCESS"),
                "OpenDrawer", List.of("SUCCESS"), "GraspBox", List.of("RUNNING", "SUCCESS"),
                "RecoveryRotate", List.of("SUCCESS"), "SlowDownSign", List.of("SUCCESS"),
                "CallElevator", List.of("RUNNING", "SUCCESS"), "Handover", List.of("RUNNING", "SUCCESS"),
                "Speak", List.of("SUCCESS"), "Dispense", List.of("RUNNING", "SUCCESS")));
        variants(s, 1, Map.of("navigation", "elevator", "preparation", "charge", "courtesy", "announce"));
        variants(s, 6, Map.of("navigation", "careful", "courtesy", "disinfect")); // the ride is halted
        variants(s, 13, Map.of("navigation", "normal", "preparation", "none", "courtesy", "silent"));
        assertSameTicks(s);
    }

    private static ObjectNode scenario(String tree, int ticks, List<String> keys) {
        ObjectNode s = Json.object();
        s.put("tree", tree);
        s.put("ticks", ticks);
        keys.forEach(s.putArray("blackboard")::add);
        s.putObject("actions");
        s.putObject("variants");
        return s;
    }

    private static void actions(ObjectNode s, Map<String, List<String>> actions) {
        actions.forEach((id, statuses) -> statuses.forEach(((ObjectNode) s.get("actions")).putArray(id)::add));
    }

    private static void variants(ObjectNode s, int tick, Map<String, String> decisions) {
        ObjectNode at = ((ObjectNode) s.get("variants")).putObject(Integer.toString(tick));
        decisions.forEach(at::put);
    }

    private void assertSameTicks(ObjectNode s) throws Exception {
        Path file = woven.resolve(s.get("tree").asText().replace(".ext.xml", "") + "-scenario.json");
        Files.writeString(file, Json.write(s));
        List<String> cpp = new ArrayList<>();
        for (JsonNode tick : BtcppRunner.scripted(file)) {
            cpp.add(Json.write(tick));
        }
        List<String> java = javaRun(s, woven.resolve(s.get("tree").asText()));
        assertEquals("ticks", s.get("ticks").asInt(), cpp.size());
        for (int i = 0; i < java.size(); i++) {
            assertEquals("tick " + (i + 1), java.get(i), normalise(cpp.get(i)));
        }
        // the scenario exercises what it claims to: skills started, halted, and a branch switch
        String all = String.join("\n", cpp);
        assertTrue(all, all.contains(":halt"));
        assertTrue(all, all.contains(":run:SUCCESS"));
    }

    /** The same record as the runner prints, from the Java executor. */
    private static List<String> javaRun(ObjectNode s, Path tree) throws Exception {
        List<String> trace = new ArrayList<>();
        ActionRegistry registry = new ActionRegistry();
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        for (Iterator<Map.Entry<String, JsonNode>> it = s.get("actions").fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            List<String> statuses = new ArrayList<>();
            e.getValue().forEach(v -> statuses.add(v.asText()));
            int[] next = { 0 };
            registry.register(e.getKey(), spec -> new AsyncActionNode(spec.info(), new AsyncAction() {
                private NodeStatus take(String phase) {
                    String status = statuses.get(Math.min(next[0]++, statuses.size() - 1));
                    trace.add(spec.info().name() + ":" + phase + ":" + status);
                    return NodeStatus.valueOf(status);
                }

                @Override
                public NodeStatus onStart(Ports ports) {
                    return take("start");
                }

                @Override
                public NodeStatus onRunning(Ports ports) {
                    return take("run");
                }

                @Override
                public void onHalted() {
                    trace.add(spec.info().name() + ":halt");
                }
            }));
        }
        Tree built = new TreeBuilder(registry, new TreeContext()).build(tree);
        List<String> records = new ArrayList<>();
        for (int n = 1; n <= s.get("ticks").asInt(); n++) {
            trace.clear();
            s.get("variants").path(Integer.toString(n)).fields().forEachRemaining(e -> variants.publish(e.getKey(), e.getValue().asText()));
            NodeStatus status = built.tickRoot();
            ObjectNode record = Json.object();
            record.put("tick", n);
            record.put("status", status.name());
            trace.forEach(record.putArray("trace")::add);
            ObjectNode board = record.putObject("blackboard");
            s.get("blackboard").forEach(k -> {
                String key = k.asText();
                board.put(key, built.blackboard().get(key).map(v -> ScriptValues.toText(ScriptValues.of(v))).orElse(null));
            });
            records.add(normalise(Json.write(record)));
        }
        return records;
    }

    /** Key order aside (the runner's JSON sorts keys). */
    private static String normalise(String json) throws Exception {
        JsonNode node = Json.MAPPER.readTree(json);
        return node.path("tick").asInt() + " " + node.path("status").asText() + " " + node.path("trace") + " "
                + Json.MAPPER.convertValue(node.path("blackboard"), java.util.TreeMap.class);
    }
}
