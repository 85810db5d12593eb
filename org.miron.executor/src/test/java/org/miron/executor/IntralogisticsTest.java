package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.Before;
import org.junit.Test;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;
import org.miron.executor.skills.VariantSource;

/** The seed's intralogistics tree, nominal and woven, with Java actions and with skills. */
public class IntralogisticsTest {
    private final ActionRegistry registry = new ActionRegistry();
    private final List<String> calls = new ArrayList<>();
    private final TraceRecorder trace = new TraceRecorder();
    /** navigate takes this many RUNNING ticks before it arrives (-1: never). */
    private int navigateTicks = 2;
    private int navigateHalts;

    @Before
    public void setUp() {
        registry.registerAsync("navigate", () -> new AsyncAction() {
            private int left;

            @Override
            public NodeStatus onStart(Ports ports) {
                calls.add("navigate(" + ports.getDouble("x").orElseThrow() + "," + ports.getDouble("y").orElseThrow() + ")");
                left = navigateTicks;
                return onRunning(ports);
            }

            @Override
            public NodeStatus onRunning(Ports ports) {
                if (left == 0) {
                    return SUCCESS;
                }
                if (left > 0) {
                    left--;
                }
                return RUNNING;
            }

            @Override
            public void onHalted() {
                calls.add("halted navigate");
                navigateHalts++;
            }
        });
        registry.registerSync("objectpick", ports -> {
            calls.add("objectpick(" + ports.getInt("obj_index").orElseThrow() + ")");
            return SUCCESS;
        });
        registry.registerSync("objectdrop", ports -> {
            calls.add("objectdrop(" + ports.getInt("obj_index").orElseThrow() + ")");
            return SUCCESS;
        });
    }

    private Tree build(String file) {
        TreeContext context = new TreeContext();
        context.addListener(trace);
        return new TreeBuilder(registry, context).build(Fixtures.resource(file));
    }

    @Test
    public void runsPickDeliverChargeToCompletion() {
        Tree tree = build("intralogistics.bt");
        assertEquals("Main", tree.id());
        assertEquals(SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        assertEquals(List.of(
                "navigate(-6.5,1.25)", "objectpick(3)",
                "navigate(-8.08,4.11)", "objectdrop(-1)",
                "navigate(-9.33,2.17)"), calls);
        assertEquals(0, navigateHalts);
    }

    @Test
    public void takesOneTickPerRunningStep() {
        Tree tree = build("intralogistics.bt");
        int ticks = 1;
        while (tree.tickRoot() == RUNNING) {
            ticks++;
        }
        assertEquals("three trips of two RUNNING ticks, the last tick succeeds", 7, ticks);
    }

    @Test
    public void traceFollowsTheNodesThroughTheirSubtrees() {
        Tree tree = build("intralogistics.bt");
        tree.tickWhileRunning(Duration.ZERO);
        String drop = "Main/PickDeliverChargeSubtree/pickDeliverCharge/Deliver/deliver/objectdrop";
        assertEquals(List.of(drop + " IDLE->SUCCESS", drop + " SUCCESS->IDLE"), trace.of(drop));
        assertEquals("Main/PickDeliverChargeSubtree RUNNING->SUCCESS", trace.of("Main/PickDeliverChargeSubtree").get(1));
        List<String> navigate = trace.of("Charge/Charge/GoTo/goTo/navigate");
        assertEquals(List.of("IDLE->RUNNING", "RUNNING->SUCCESS", "SUCCESS->IDLE"),
                navigate.stream().map(l -> l.substring(l.lastIndexOf(' ') + 1)).toList());
    }

    @Test
    public void wovenTreeFollowsTheVariantAndHaltsTheBranchItLeaves() {
        VariantSource variants = new VariantSource();
        registry.registerVariantAction(variants);
        navigateTicks = -1;
        Tree tree = build("intralogistics.ext.xml");

        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("no decision yet: the default branch runs", List.of("navigate(-6.5,1.25)"), calls);

        variants.publish("task", "dock");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("dock", tree.blackboard().get("task_sel").orElseThrow());
        assertEquals(List.of("navigate(-6.5,1.25)", "halted navigate", "navigate(-9.33,2.17)"), calls);

        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("same decision: nothing restarts", 3, calls.size());

        navigateTicks = 0;
        variants.publish("task", "deliver");
        assertEquals("DeliverCharge runs through at once, so the monitoring parallel succeeds", SUCCESS, tree.tickRoot());
        assertEquals(List.of("halted navigate", "navigate(-8.08,4.11)", "objectdrop(-1)", "navigate(-9.33,2.17)"),
                calls.subList(3, calls.size()));
        assertEquals(2, navigateHalts);
        assertTrue(tree.nodes().stream().allMatch(n -> n.status() == NodeStatus.IDLE));
    }

    @Test
    public void unregisteredActionsBecomePushSkillRequestsAndAreAbortedWhenHalted() {
        FakeSkillClient skills = new FakeSkillClient();
        ActionRegistry skillsOnly = new ActionRegistry().setFallback(new SkillActionStrategy(skills));
        VariantSource variants = new VariantSource();
        skillsOnly.registerVariantAction(variants);
        Tree tree = new TreeBuilder(skillsOnly, new TreeContext()).build(Fixtures.load("intralogistics.ext.xml"));

        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(new SkillRequest("navigate", Map.of("x", -6.5, "y", 1.25)), skills.last());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("a running skill is pushed once", 1, skills.requests.size());

        skills.completeLast(SkillResult.Outcome.SUCCESS);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(new SkillRequest("objectpick", Map.of("obj_index", 3)), skills.requests.get(1));
        skills.completeLast(SkillResult.Outcome.SUCCESS);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(new SkillRequest("navigate", Map.of("x", -8.08, "y", 4.11)), skills.last());

        variants.publish("task", "dock");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("the Switch left the running skill: it is aborted", 1, skills.aborts);
        assertEquals(new SkillRequest("navigate", Map.of("x", -9.33, "y", 2.17)), skills.last());

        skills.completeLast(SkillResult.Outcome.ERROR);
        assertEquals("a skill error fails the branch, and the parallel", NodeStatus.FAILURE, tree.tickRoot());
        assertTrue(tree.nodes().stream().allMatch(n -> n.status() == NodeStatus.IDLE));
    }
}
