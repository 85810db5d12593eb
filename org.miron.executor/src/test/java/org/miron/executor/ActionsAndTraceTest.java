package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.IDLE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.time.ZoneOffset;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.Test;
import org.miron.executor.actions.AlwaysFailureNode;
import org.miron.executor.skills.SkillActionNode;
import org.miron.executor.skills.SkillActionStrategy;
import org.miron.executor.skills.SkillResult;
import org.miron.executor.skills.VariantActionNode;
import org.miron.executor.skills.VariantSource;
import org.miron.executor.trace.ConsoleTracePrinter;

/** Action plug-in point, variant and blackboard feeds, the tick loop and the console trace. */
public class ActionsAndTraceTest {
    private final ActionRegistry registry = new ActionRegistry();

    private Tree controls(String id, TreeContext context) {
        return Fixtures.build("controls.bt", id, registry, context);
    }

    @Test
    public void asyncActionsRunOverSeveralTicksAndAreToldWhenHalted() {
        ScriptedAction a = ScriptedAction.register(registry, "A");
        ScriptedAction.register(registry, "B").returns(RUNNING);
        ScriptedAction.register(registry, "C");
        Tree tree = controls("Seq", new TreeContext());
        tree.tickRoot();
        assertEquals(SUCCESS, tree.find("A").get().status());
        assertEquals(RUNNING, tree.find("B").get().status());
        tree.haltTree();
        assertEquals(IDLE, tree.find("A").get().status());
        assertEquals(IDLE, tree.find("B").get().status());
        assertEquals("A had finished: it is not told", 0, a.halts);
    }

    @Test
    public void aSyncActionReturningRunningIsAnError() {
        registry.registerSync("A", ports -> RUNNING);
        registry.registerSync("B", ports -> SUCCESS);
        registry.registerSync("C", ports -> SUCCESS);
        try {
            controls("Seq", new TreeContext()).tickRoot();
            fail();
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("Seq/Sequence/A"));
        }
    }

    @Test
    public void aNodeReturningIdleIsAnError() {
        registry.register("A", spec -> new Node(spec.info()) {
            @Override
            protected NodeStatus tick() {
                return IDLE;
            }
        });
        registry.registerSync("B", ports -> SUCCESS);
        registry.registerSync("C", ports -> SUCCESS);
        try {
            controls("Seq", new TreeContext()).tickRoot();
            fail();
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("IDLE"));
        }
    }

    @Test
    public void anUnregisteredActionIsABuildErrorByDefaultAndGoesToTheFallbackOtherwise() {
        try {
            new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("unknown-action.bt"));
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("'NotRegistered'"));
        }
        registry.setFallback(spec -> new AlwaysFailureNode(spec.info()));
        assertEquals(FAILURE, new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("unknown-action.bt")).tickRoot());
    }

    @Test
    public void conditionsAreNotTurnedIntoSkills() {
        registry.setFallback(new SkillActionStrategy(new FakeSkillClient()));
        ScriptedAction.register(registry, "A");
        ScriptedAction.register(registry, "B");
        try {
            controls("ReactiveSeq", new TreeContext());
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("condition 'Cond'"));
        }
    }

    @Test
    public void skillOutputsAreWrittenToBlackboardPorts() {
        FakeSkillClient skills = new FakeSkillClient();
        Ports ports = new Ports("detect", java.util.Map.of("ID", "detect", "where", "{place}", "found", "{obj}", "mode", "fast"),
                Blackboard.create());
        ports.blackboard().set("place", "table");
        // found is declared an output_port (TreeNodesModel): written from the result, not sent
        SkillActionNode node = new SkillActionNode(NodeInfo.of("detect", ports, new TreeContext()), "detect", skills,
                java.util.Set.of("found"));
        assertEquals(RUNNING, node.executeTick());
        assertEquals(java.util.Map.of("where", "table", "mode", "fast"), skills.last().inAttributes());
        skills.results.get(0).complete(new SkillResult(SkillResult.Outcome.SUCCESS, null, java.util.Map.of("found", "cup", "mode", "x")));
        assertEquals(SUCCESS, node.executeTick());
        assertEquals(Optional.of("cup"), ports.blackboard().get("obj"));
        assertEquals("a literal port is not an output", Optional.empty(), ports.blackboard().get("x"));
    }

    @Test
    public void variantActionWritesTheLatestDecisionAndStaysRunning() {
        VariantSource variants = new VariantSource();
        Ports ports = new Ports(java.util.Map.of("ID", "VariantAction", "varpoint", "task", "value", "{task_sel}"), Blackboard.create());
        VariantActionNode node = new VariantActionNode(NodeInfo.of("VariantAction", ports, new TreeContext()), variants);
        assertEquals(RUNNING, node.executeTick());
        assertEquals(Optional.empty(), ports.blackboard().get("task_sel"));
        variants.publish("task", "dock");
        variants.publish("other", "x");
        assertEquals(RUNNING, node.executeTick());
        assertEquals(Optional.of("dock"), ports.blackboard().get("task_sel"));
    }

    @Test
    public void numericDecisionsAreFedToTheRootBlackboardBeforeEachTick() {
        VariantSource numbers = new VariantSource();
        registry.registerSync("A", ports -> SUCCESS);
        registry.registerSync("B", ports -> SUCCESS);
        registry.registerSync("C", ports -> SUCCESS);
        Tree tree = controls("Seq", new TreeContext());
        tree.feedBlackboardFrom(numbers);
        numbers.publish("speed", 0.5);
        tree.tickRoot();
        assertEquals(Optional.of(0.5), tree.blackboard().get("speed"));
        tree.blackboard().set("speed", 0.1);
        tree.tickRoot();
        assertEquals("unchanged decisions are not written again", Optional.of(0.1), tree.blackboard().get("speed"));
        numbers.publish("speed", 0.7);
        tree.tickRoot();
        assertEquals(Optional.of(0.7), tree.blackboard().get("speed"));
    }

    @Test
    public void stopMakesTickWhileRunningHaltTheTreeAndReturn() throws Exception {
        ScriptedAction.register(registry, "A");
        ScriptedAction b = ScriptedAction.register(registry, "B").returns(RUNNING);
        ScriptedAction.register(registry, "C");
        Tree tree = controls("Seq", new TreeContext());
        CountDownLatch running = new CountDownLatch(1);
        tree.addListener((time, node, from, to) -> {
            if (to == RUNNING) {
                running.countDown();
            }
        });
        NodeStatus[] result = new NodeStatus[1];
        Thread ticker = new Thread(() -> result[0] = tree.tickWhileRunning(Duration.ofMillis(1)));
        ticker.start();
        assertTrue(running.await(30, TimeUnit.SECONDS));
        tree.stop();
        ticker.join(30_000);
        assertEquals(RUNNING, result[0]);
        assertEquals(1, b.halts);
        assertEquals(IDLE, tree.root().status());
    }

    /** A stop between two runs (a robot going round its missions) ends the next run, once. */
    @Test
    public void aStopBetweenRunsEndsTheNextRunOnce() {
        ScriptedAction a = ScriptedAction.register(registry, "A");
        ScriptedAction.register(registry, "B");
        ScriptedAction.register(registry, "C");
        Tree tree = controls("Seq", new TreeContext());
        assertEquals(SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        int ticks = a.ticks;
        tree.stop();
        assertEquals(RUNNING, tree.tickWhileRunning(Duration.ZERO));
        assertEquals("nothing ticked", ticks, a.ticks);
        assertEquals(SUCCESS, tree.tickWhileRunning(Duration.ZERO));
        assertTrue(a.ticks > ticks);
    }

    @Test
    public void consoleTracePrintsTimePathAndTransition() {
        registry.registerSync("A", ports -> SUCCESS);
        registry.registerSync("B", ports -> FAILURE);
        registry.registerSync("C", ports -> SUCCESS);
        FakeClock clock = new FakeClock();
        clock.now = 3_723_045; // 01:02:03.045 UTC
        TreeContext context = new TreeContext(clock);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        context.addListener(new ConsoleTracePrinter(new PrintStream(bytes, true, StandardCharsets.UTF_8), ZoneOffset.UTC, false));
        controls("Seq", context).tickRoot();
        assertEquals(String.join(System.lineSeparator(),
                "01:02:03.045  Seq/Sequence  IDLE -> RUNNING",
                "01:02:03.045  Seq/Sequence/A  IDLE -> SUCCESS",
                "01:02:03.045  Seq/Sequence/B  IDLE -> FAILURE",
                "01:02:03.045  Seq/Sequence  RUNNING -> FAILURE") + System.lineSeparator(),
                bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    public void aFailingListenerDoesNotStopTheTree() {
        registry.registerSync("A", ports -> SUCCESS);
        registry.registerSync("B", ports -> SUCCESS);
        registry.registerSync("C", ports -> SUCCESS);
        TreeContext context = new TreeContext();
        context.addListener((time, node, from, to) -> {
            throw new IllegalStateException("broken monitor");
        });
        assertEquals(SUCCESS, controls("Seq", context).tickRoot());
    }

    @Test
    public void renderShowsTheTreeWithStatuses() {
        registry.registerSync("A", ports -> SUCCESS);
        ScriptedAction.register(registry, "B").returns(RUNNING);
        registry.registerSync("C", ports -> SUCCESS);
        Tree tree = controls("Seq", new TreeContext());
        tree.tickRoot();
        assertEquals("Sequence [RUNNING]\n  A [SUCCESS]\n  B [RUNNING]\n  C [IDLE]\n", tree.render());
    }

    @Test
    public void futureActionsRunUntilTheirFutureCompletesAndAreCancelledWhenHalted() {
        java.util.List<java.util.concurrent.CompletableFuture<NodeStatus>> started = new java.util.ArrayList<>();
        registry.registerFuture("A", ports -> {
            java.util.concurrent.CompletableFuture<NodeStatus> f = new java.util.concurrent.CompletableFuture<>();
            started.add(f);
            return f;
        });
        registry.registerSync("B", ports -> SUCCESS);
        registry.registerSync("C", ports -> SUCCESS);
        Tree tree = controls("Seq", new TreeContext());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        started.get(0).complete(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        tree.haltTree();
        assertTrue(started.get(1).isCancelled());
        assertEquals(RUNNING, tree.tickRoot());
        started.get(2).completeExceptionally(new IllegalStateException("motor fault"));
        assertEquals(FAILURE, tree.tickRoot());
    }

    @Test
    public void anUnreachableSkillInterfaceFailsTheActionWithoutStoppingTheTree() {
        Ports ports = new Ports(java.util.Map.of("ID", "dock"), Blackboard.create());
        SkillActionNode node = new SkillActionNode(NodeInfo.of("dock", ports, new TreeContext()), "dock", request -> {
            throw new IllegalStateException("no route to host");
        });
        assertEquals(FAILURE, node.executeTick());
        assertTrue(node.lastError().get(), node.lastError().get().contains("no route to host"));
    }

    @Test
    public void consoleTraceAlwaysShowsHalts() {
        registry.registerSync("A", ports -> SUCCESS);
        ScriptedAction.register(registry, "B").returns(RUNNING);
        registry.registerSync("C", ports -> SUCCESS);
        FakeClock clock = new FakeClock();
        clock.now = 0;
        TreeContext context = new TreeContext(clock);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        context.addListener(new ConsoleTracePrinter(new PrintStream(bytes, true, StandardCharsets.UTF_8), ZoneOffset.UTC, false));
        Tree tree = controls("Seq", context);
        tree.tickRoot();
        bytes.reset();
        tree.haltTree();
        assertEquals(String.join(System.lineSeparator(),
                "00:00:00.000  Seq/Sequence/B  RUNNING -> IDLE  (halted)",
                "00:00:00.000  Seq/Sequence  RUNNING -> IDLE  (halted)") + System.lineSeparator(),
                bytes.toString(StandardCharsets.UTF_8));
    }
}
